// What the water lies in front of, drawn before it: the sky, the ground, the box's floor and far
// walls (its near walls are glass, left out so the water shows) and the solid obstacles, each found
// by casting the pixel's ray analytically (a fullscreen pass, no meshes). The fluid shading refracts
// this picture and compares its depth with the water's. It is kept between pictures and redrawn only
// when the camera, the size or the geometry changed (a still camera costs nothing).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "decoded_frame.h"
#include "fullscreen_pass.h"
#include "gl_program.h"
#include "texture_target.h"

namespace viewer {

class SceneBackdrop {
 public:
  SceneBackdrop();
  // The geometry of the frame being shown (a few obstacles; extra ones are left out).
  void setGeometry(const SceneGeometry& geometry);
  // Brings the pictures up to date for this camera and size (draws only when something changed;
  // changes the bound framebuffer and viewport when it does). True when it drew.
  bool update(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection, int width, int height,
              const FullscreenTriangle& triangle);
  GLuint colour() const { return target_.texture(0); }
  GLuint depth() const { return target_.texture(1); }  // metres along the view axis; kFar: only sky

  static constexpr int kMaxObstacles = 8;  // of each kind

 private:
  void draw(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection, const FullscreenTriangle& triangle) const;

  GlProgram program_;
  TextureTarget target_{{{GL_RGBA8, GL_LINEAR}, {GL_R32F, GL_NEAREST}}};
  std::vector<float> shapes_;  // box flag, min, max, cylinder span; then spheres (x, y, z, r), cylinders (x, z, r)
  int sphere_count_ = 0;
  int cylinder_count_ = 0;
  bool stale_ = true;
  Eigen::Matrix4f drawn_view_ = Eigen::Matrix4f::Zero();
  Eigen::Matrix4f drawn_projection_ = Eigen::Matrix4f::Zero();
};

}  // namespace viewer
