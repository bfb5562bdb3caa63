// The last two fluid passes (Green 2010, "Screen Space Fluid Rendering for Games", GDC; van der
// Laan, Green & Sainz 2009, section 4).
// Shade, at the surface passes' resolution: per pixel with water in front of the backdrop
//  - the normal from the smoothed depth, each axis by the smaller of the forward and backward
//    differences so that silhouettes do not bleed into the normals (Green 2010);
//  - Fresnel (Schlick, F0 = 0.02) between the reflected sky and the refracted backdrop, which is
//    sampled offset along the normal by an amount that grows with thickness;
//  - Beer-Lambert absorption by thickness, exp(-sigma t) per colour channel, towards a deep-water
//    colour; a Blinn-Phong highlight of the sun;
// written as premultiplied colour with coverage in alpha, and the depth of whichever is nearer,
// water or backdrop.
// Present, at the picture's resolution: the water over the backdrop (bilinear, so a half-resolution
// surface gets soft edges rather than steps), and that depth into the depth buffer, so that
// outlines drawn afterwards hide behind the water and the obstacles.
#pragma once

#include <Eigen/Core>

#include "fullscreen_pass.h"
#include "gl_program.h"
#include "render_settings.h"

namespace viewer {

struct ShadeInputs {
  GLuint surface_depth;   // smoothed, metres along the view axis (kFar: no water)
  GLuint thickness;       // metres of water along the ray (sum of sphere chords)
  GLuint backdrop;        // colour
  GLuint backdrop_depth;  // metres along the view axis (kFar: sky)
  float step_m;           // a depth step larger than this between neighbours is a silhouette
  float guard;            // texels of the surface textures beyond each edge of the picture
};

struct PresentInputs {
  GLuint water;     // the shade pass's colour (premultiplied) and coverage
  GLuint depth;     // the shade pass's depth (metres along the view axis)
  GLuint backdrop;  // colour
  int scale;        // picture pixels per shaded pixel, each way
};

class FluidComposite {
 public:
  FluidComposite();
  // Into the bound framebuffer (the picture at the surface textures' scale, without their guard
  // band): attachment 0 the colour and coverage, attachment 1 the depth. With a debug mode the
  // colour is that mode's encoding (render_settings.h).
  void shade(const ShadeInputs& inputs, const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
             RenderDebug debug, const FullscreenTriangle& triangle) const;
  // Into the bound framebuffer, colour and depth (depth test on with GL_ALWAYS, set by the caller).
  void present(const PresentInputs& inputs, const Eigen::Matrix4f& projection, RenderDebug debug,
               const FullscreenTriangle& triangle) const;

 private:
  GlProgram shade_;
  GlProgram present_;
  GlProgram present_debug_;
};

}  // namespace viewer
