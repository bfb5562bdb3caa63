// GLSL pieces more than one program uses, and a way to put a program's source together from them.
#pragma once

#include <initializer_list>
#include <string>

namespace viewer {

// "#version 330 core" and the constants and functions every fluid-mode program may call:
//   kFar                     depth of "nothing here" in the depth targets (metres)
//   kSunDirection            the one light, world space, towards the sun
//   vec3 skyColour(vec3 d)   the procedural environment seen along world direction d
//   vec3 encodeMetres(float) the 24-bit fixed-point debug encoding of render_settings.h
//   float windowDepth(float metres, vec2 depth_proj)  depth along the view axis -> depth buffer
//                            value; depth_proj = projection (2,2), (2,3); kFar -> 1
extern const char* const kGlslCommon;

// The parts joined in order (each a complete line or block).
std::string glslSource(std::initializer_list<const char*> parts);

}  // namespace viewer
