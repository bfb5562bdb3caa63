#include "glsl_common.h"

namespace viewer {

const char* const kGlslCommon = R"(#version 330 core
const float kFar = 1.0e4;
const vec3 kSunDirection = vec3(0.3464, 0.8083, 0.4619);  // normalize(0.3, 0.7, 0.4)

// A studio sky: a cool zenith, a bright horizon, a darker ground below it and a small sun. It is the
// backdrop where no geometry is and what the water reflects (Fresnel term of the shading). Powers
// are products: software GL (llvmpipe) runs every pixel through all of it.
vec3 skyColour(vec3 d) {
  vec3 zenith = vec3(0.16, 0.27, 0.45);
  vec3 horizon = vec3(0.62, 0.68, 0.74);
  vec3 ground = vec3(0.22, 0.21, 0.20);
  vec3 c = d.y >= 0.0 ? mix(horizon, zenith, sqrt(d.y)) : mix(horizon * 0.7, ground, min(1.0, -d.y * 5.0));
  float sun = max(dot(d, kSunDirection), 0.0);
  float s4 = sun * sun * sun * sun;
  float s32 = s4 * s4 * s4 * s4 * s4 * s4 * s4 * s4;
  return c + vec3(1.0, 0.95, 0.85) * (0.12 * s32 + 3.0 * smoothstep(0.9985, 0.9995, sun));
}

float windowDepth(float depth, vec2 depth_proj) {
  return depth >= kFar ? 1.0 : clamp(0.5 * (depth_proj.x * -depth + depth_proj.y) / depth + 0.5, 0.0, 1.0);
}

vec3 encodeMetres(float metres) {
  uint v = uint(clamp(metres, 0.0, 255.99) * 65536.0 + 0.5);
  return vec3(float((v >> 16) & 255u), float((v >> 8) & 255u), float(v & 255u)) / 255.0;
}
)";

std::string glslSource(std::initializer_list<const char*> parts) {
  std::string source;
  for (const char* part : parts) source += part;
  return source;
}

}  // namespace viewer
