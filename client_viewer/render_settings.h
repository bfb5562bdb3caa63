// How sph_viewer draws the particles: the render mode (--render, the panel's switch) and the debug
// outputs that encode what a fluid pass computed instead of the shaded picture (--render-debug).
#pragma once

namespace viewer {

enum class RenderMode {
  kFluid,     // a liquid surface in screen space (fluid_renderer.h)
  kParticles  // sphere impostors coloured by size class or speed, for research
};

// Encodings (client_viewer/README.md, "Debug outputs"): kNormals writes the view-space normal n as
// RGB = 255 (n + 1) / 2, no water black; kDepth and kThickness write metres as a 24-bit fixed-point
// number, RGB = the big-endian bytes of round(metres * 65536), no water white. Debug pictures leave
// out spray, outlines and overlays, so every pixel is the pass's output.
enum class RenderDebug { kNone = 0, kNormals = 1, kDepth = 2, kThickness = 3 };  // values as the shaders take them

}  // namespace viewer
