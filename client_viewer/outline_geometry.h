// Line geometry for what the viewer draws as outlines: the box, sphere and cylinder obstacles (world
// space) and the gaze circle and hysteresis ring (normalized device coordinates). Plain data, no GL,
// so the shapes are unit tested.
#pragma once

#include <vector>

#include "decoded_frame.h"
#include "level_colours.h"

namespace viewer {

struct LineVertex {
  float x, y, z;
  float r, g, b;
};
using LineList = std::vector<LineVertex>;  // pairs of vertices, drawn as GL_LINES

struct Rgb {
  float r, g, b;
};

void appendBox(LineList& lines, const Vec3f& lo, const Vec3f& hi, Rgb colour);
// Three great circles (one per axis plane).
void appendSphere(LineList& lines, const SphereShape& sphere, Rgb colour);
// A vertical cylinder from y_floor to y_roof: two circles and four vertical lines.
void appendCylinder(LineList& lines, const CylinderShape& cylinder, float y_floor, float y_roof, Rgb colour);
// The box and, unless `obstacles` is false (fluid mode draws them solid), the obstacles.
void appendGeometry(LineList& lines, const SceneGeometry& geometry, bool obstacles = true);

// A circle on the screen given as the protocol does: centre normalized 0..1 with the origin at the
// top left, radius as a fraction of the viewport width. Output in NDC (x right, y up), z = 0.
void appendScreenCircle(LineList& lines, float x, float y, float radius_of_width, float aspect, Rgb colour,
                        bool dashed = false);
// The gaze circle and, when wider, the REMAIN ring around it, coloured by the gaze mode.
void appendGazeOverlay(LineList& lines, const GazeOverlay& gaze, float aspect);

// The foveated method's rings: where each coarser level begins around the gaze point the step used,
// radii as the server sent them (viewport widths), each in its level's colour (level_colours.h);
// dashed while the gaze is held or lost. Rings of radius 0 (the level is allowed at the gaze point)
// are left out.
void appendFoveaRings(LineList& lines, const DecodedFrame& frame, float aspect);
// What the frame's method used: the rings for foveated, the gaze circle for gaze and hybrid,
// nothing for the others.
void appendMethodOverlay(LineList& lines, const DecodedFrame& frame, float aspect);

// A small cross at a normalized screen point (the mouse gaze, when it is being sent).
void appendScreenCross(LineList& lines, float x, float y, float size_of_width, float aspect, Rgb colour);

}  // namespace viewer
