// Reading sph_viewer's fluid-mode pictures back into numbers for the window tests: the debug
// encodings of client_viewer/render_settings.h (view-space normals, metres), the camera a picture
// was drawn with (the pose the viewer sent), and running the viewer for one snapshot.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "camera_reference.h"
#include "png_image.h"
#include "proto/sph.pb.h"
#include "test_frames.h"
#include "test_publisher.h"

namespace viewer_test {

// Runs sph_viewer with `args` (plus the server's endpoints, `--viewer-id id` and a snapshot into
// `dir`) until it has written its picture; the picture and the pose it was drawn with. Records a
// test failure (with the viewer's log) and returns nullopt when that does not happen.
struct Snapshot {
  viewer::RgbaImage image;
  gsph::v1::CameraPose pose;
};
std::optional<Snapshot> takeSnapshot(TestServer& server, std::vector<std::string> args, const std::string& dir,
                                     const std::string& id);

// The view-space unit normal a --render-debug normals pixel holds; nullopt where there is no water.
std::optional<Vec3d> decodeNormal(const viewer::RgbaImage& image, int x, int y);
// The metres a --render-debug depth or thickness pixel holds; nullopt where there is no water.
std::optional<double> decodeMetres(const viewer::RgbaImage& image, int x, int y);

double angleDegrees(const Vec3d& a, const Vec3d& b);
// A world direction in the view space of `pose` (rotation only).
Vec3d toView(const gsph::v1::CameraPose& pose, const Vec3d& world);
// The world point at `depth` metres along the view axis behind pixel (x, y)'s centre.
Vec3d worldPoint(const gsph::v1::CameraPose& pose, int x, int y, double depth);

// The spacing of the server's lattice for particles of radius r: a particle's sphere holds its
// volume, r = cbrt(3 m / (4 pi rho0)) (server/sph/params.h), on a lattice of cbrt(m / rho0).
inline constexpr double kSpacingPerRadius = 1.6119919540164696;  // cbrt(4 pi / 3)

// Particles of one class on that cubic lattice, whose top layer's tops are at y = top: `layers`
// layers over x in [x0, x1], z in [z0, z1]. The spheres at the ends reach x0 and x1 exactly when
// the span is a whole number of spacings; columns are counted from x0 (or from x1 when `from_x1`),
// so two halves can meet at one x.
void appendPool(std::vector<TestParticle>& out, double x0, double x1, double z0, double z1, double top, int layers,
                double radius, std::uint8_t size_class, bool from_x1 = false);

}  // namespace viewer_test
