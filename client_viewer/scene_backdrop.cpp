#include "scene_backdrop.h"

#include <algorithm>
#include <utility>

#include "glsl_common.h"

namespace viewer {

namespace {

constexpr std::size_t kHeader = 9;  // of shapes_: has box, box min (3), box max (3), cylinder span (2)

const char* const kFragmentShader = R"(
uniform mat3 u_view_to_world;
uniform vec3 u_eye;
uniform vec2 u_proj_scale;  // projection (0,0) and (1,1)
uniform int u_has_box;
uniform vec3 u_box_min;
uniform vec3 u_box_max;
uniform vec4 u_spheres[8];
uniform int u_sphere_count;
uniform vec3 u_cylinders[8];  // x, z, radius
uniform int u_cylinder_count;
uniform vec2 u_cylinder_span;  // floor and roof height
in vec2 v_uv;
layout(location = 0) out vec4 o_colour;
layout(location = 1) out float o_depth;

vec3 lit(vec3 albedo, vec3 n) { return albedo * (0.45 + 0.55 * max(dot(n, kSunDirection), 0.0)); }

// Floor tiles of 10 cm, two tones, so refraction through the water shows as bent lines.
vec3 floorColour(vec3 p) {
  float checker = mod(floor(p.x * 10.0) + floor(p.z * 10.0), 2.0);
  return lit(mix(vec3(0.70, 0.68, 0.63), vec3(0.55, 0.53, 0.50), checker), vec3(0.0, 1.0, 0.0));
}

vec3 wallColour(vec3 p, vec3 n) {
  vec2 q = abs(n.x) > 0.5 ? p.zy : p.xy;
  vec2 f = abs(fract(q * 10.0) - 0.5);
  float line = step(0.46, max(f.x, f.y));
  return lit(mix(vec3(0.46, 0.52, 0.58), vec3(0.38, 0.43, 0.49), line), n);
}

void main() {
  vec3 ray_view = normalize(vec3((v_uv * 2.0 - 1.0) / u_proj_scale, -1.0));
  vec3 dir = u_view_to_world * ray_view;
  float t_best = kFar;
  vec3 colour = skyColour(dir);
  if (u_has_box == 1) {
    // Slabs: the ray leaves the box through its floor, a far wall or the open top.
    vec3 inv = 1.0 / (dir + vec3(equal(dir, vec3(0.0))) * 1e-9);
    vec3 t0 = (u_box_min - u_eye) * inv;
    vec3 t1 = (u_box_max - u_eye) * inv;
    vec3 t_out = max(t0, t1);
    float t_far = min(min(t_out.x, t_out.y), t_out.z);
    float t_near = max(max(min(t0.x, t1.x), min(t0.y, t1.y)), min(t0.z, t1.z));
    if (t_far > max(t_near, 0.0)) {
      vec3 p = u_eye + t_far * dir;
      if (t_far == t_out.y) {
        if (dir.y < 0.0) {
          t_best = t_far;
          colour = floorColour(p);
        }
      } else {
        vec3 n = t_far == t_out.x ? vec3(-sign(dir.x), 0.0, 0.0) : vec3(0.0, 0.0, -sign(dir.z));
        t_best = t_far;
        colour = wallColour(p, n);
      }
    }
  }
  // Outside the box: the ground the box stands on, large tiles fading into the haze.
  if (u_has_box == 1 && t_best >= kFar && dir.y < 0.0) {
    float t = (u_box_min.y - u_eye.y) / dir.y;
    vec3 p = u_eye + t * dir;
    float checker = mod(floor(p.x * 2.0) + floor(p.z * 2.0), 2.0);
    vec3 ground = lit(mix(vec3(0.36, 0.35, 0.33), vec3(0.31, 0.30, 0.29), checker), vec3(0.0, 1.0, 0.0));
    colour = mix(skyColour(dir), ground, exp(-t / 12.0));
    t_best = t > 0.0 ? t : kFar;
  }
  vec3 obstacle = vec3(0.78, 0.42, 0.24);
  for (int i = 0; i < u_sphere_count; ++i) {
    vec3 oc = u_eye - u_spheres[i].xyz;
    float b = dot(oc, dir);
    float disc = b * b - dot(oc, oc) + u_spheres[i].w * u_spheres[i].w;
    float t = -b - sqrt(max(disc, 0.0));
    if (disc > 0.0 && t > 0.0 && t < t_best) {
      t_best = t;
      colour = lit(obstacle, normalize(u_eye + t * dir - u_spheres[i].xyz));
    }
  }
  for (int i = 0; i < u_cylinder_count; ++i) {
    vec2 o = u_eye.xz - u_cylinders[i].xy;
    float a = dot(dir.xz, dir.xz);
    float b = dot(o, dir.xz);
    float disc = b * b - a * (dot(o, o) - u_cylinders[i].z * u_cylinders[i].z);
    float t = (-b - sqrt(max(disc, 0.0))) / max(a, 1e-12);
    float y = u_eye.y + t * dir.y;
    if (disc > 0.0 && t > 0.0 && t < t_best && y >= u_cylinder_span.x && y <= u_cylinder_span.y) {
      t_best = t;
      vec3 p = u_eye + t * dir;
      colour = lit(obstacle, normalize(vec3(p.x - u_cylinders[i].x, 0.0, p.z - u_cylinders[i].y)));
    }
    // The top cap, seen from above the roof.
    float t_cap = (u_cylinder_span.y - u_eye.y) / dir.y;
    vec3 q = u_eye + t_cap * dir;
    if (t_cap > 0.0 && t_cap < t_best && distance(q.xz, u_cylinders[i].xy) <= u_cylinders[i].z) {
      t_best = t_cap;
      colour = lit(obstacle, vec3(0.0, 1.0, 0.0));
    }
  }
  o_colour = vec4(colour, 1.0);
  o_depth = t_best < kFar ? t_best * -ray_view.z : kFar;
}
)";

}  // namespace

SceneBackdrop::SceneBackdrop()
    : program_(glslSource({kGlslCommon, kFullscreenVertexShader}).c_str(),
               glslSource({kGlslCommon, kFragmentShader}).c_str(), "backdrop") {}

void SceneBackdrop::setGeometry(const SceneGeometry& g) {
  // Cylinders run floor to roof of the box; without a box a nominal metre (as the outlines do).
  std::vector<float> shapes = {g.has_box ? 1.0f : 0.0f,
                               g.box_min.x,
                               g.box_min.y,
                               g.box_min.z,
                               g.box_max.x,
                               g.box_max.y,
                               g.box_max.z,
                               g.has_box ? g.box_min.y : 0.0f,
                               g.has_box ? g.box_max.y : 1.0f};
  const std::size_t spheres = std::min<std::size_t>(g.spheres.size(), kMaxObstacles);
  const std::size_t cylinders = std::min<std::size_t>(g.cylinders.size(), kMaxObstacles);
  for (std::size_t i = 0; i < spheres; ++i) {
    const SphereShape& s = g.spheres[i];
    shapes.insert(shapes.end(), {s.center.x, s.center.y, s.center.z, s.radius});
  }
  for (std::size_t i = 0; i < cylinders; ++i) {
    const CylinderShape& c = g.cylinders[i];
    shapes.insert(shapes.end(), {c.x, c.z, c.radius});
  }
  if (shapes == shapes_) return;  // frames of a still scene keep the picture
  shapes_ = std::move(shapes);
  sphere_count_ = static_cast<int>(spheres);
  cylinder_count_ = static_cast<int>(cylinders);
  stale_ = true;
}

bool SceneBackdrop::update(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection, int width, int height,
                           const FullscreenTriangle& triangle) {
  if (!stale_ && width == target_.width() && height == target_.height() && view == drawn_view_ &&
      projection == drawn_projection_) {
    return false;
  }
  target_.bind(width, height);
  draw(view, projection, triangle);
  drawn_view_ = view;
  drawn_projection_ = projection;
  stale_ = false;
  return true;
}

void SceneBackdrop::draw(const Eigen::Matrix4f& view, const Eigen::Matrix4f& projection,
                         const FullscreenTriangle& triangle) const {
  if (shapes_.empty()) return;
  const GLuint id = program_.id();
  glUseProgram(id);
  const Eigen::Matrix3f view_to_world = view.block<3, 3>(0, 0).transpose();
  const Eigen::Vector3f eye = -view_to_world * view.block<3, 1>(0, 3);
  glUniformMatrix3fv(program_.uniform("u_view_to_world"), 1, GL_FALSE, view_to_world.data());
  glUniform3fv(program_.uniform("u_eye"), 1, eye.data());
  glUniform2f(program_.uniform("u_proj_scale"), projection(0, 0), projection(1, 1));
  const float* h = shapes_.data();
  glUniform1i(program_.uniform("u_has_box"), h[0] > 0.5f ? 1 : 0);
  glUniform3fv(program_.uniform("u_box_min"), 1, h + 1);
  glUniform3fv(program_.uniform("u_box_max"), 1, h + 4);
  glUniform2fv(program_.uniform("u_cylinder_span"), 1, h + 7);
  const float* spheres = h + kHeader;
  const float* cylinders = spheres + 4 * sphere_count_;
  if (sphere_count_ > 0) glUniform4fv(program_.uniform("u_spheres"), sphere_count_, spheres);
  if (cylinder_count_ > 0) glUniform3fv(program_.uniform("u_cylinders"), cylinder_count_, cylinders);
  glUniform1i(program_.uniform("u_sphere_count"), sphere_count_);
  glUniform1i(program_.uniform("u_cylinder_count"), cylinder_count_);
  triangle.draw();
}

}  // namespace viewer
