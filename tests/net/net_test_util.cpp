#include "net_test_util.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include "net/frame_encoder.h"

namespace net_test {

int idleTcpConnection(const std::string& endpoint) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(std::stoi(endpoint.substr(endpoint.rfind(':') + 1))));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  (void)::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
  return fd;
}

std::vector<Eigen::Vector2d> smallOnScreen(const gsph::v1::Frame& frame, const sph::ScreenCamera& camera) {
  const std::vector<float> xyz = net::decodePositions(frame);
  const sph::Projector projector(camera);
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < frame.size_classes().size(); ++i) {
    if (frame.size_classes()[i] != 0) continue;  // L1
    const Eigen::Vector3d p(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    const sph::ScreenDisc d = projector.project(p, frame.radius_small());
    if (d.in_front) out.emplace_back(d.x, d.y);
  }
  return out;
}

int countNear(const std::vector<Eigen::Vector2d>& points, const sph::ScreenCamera& camera, double x, double y,
              double radius) {
  // Distances in units of the viewport width, as the gaze radius is measured.
  const double aspect = static_cast<double>(camera.viewport_width) / camera.viewport_height;
  int n = 0;
  for (const Eigen::Vector2d& p : points) {
    const double dx = p.x() - x;
    const double dy = (p.y() - y) / aspect;
    n += dx * dx + dy * dy <= radius * radius;
  }
  return n;
}

Eigen::Vector2d smallMeanXZ(const gsph::v1::Frame& frame) {
  const std::vector<float> xyz = net::decodePositions(frame);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int n = 0;
  for (std::size_t i = 0; i < frame.size_classes().size(); ++i) {
    if (frame.size_classes()[i] != 0) continue;
    sum += Eigen::Vector2d(xyz[3 * i], xyz[3 * i + 2]);
    ++n;
  }
  return n > 0 ? Eigen::Vector2d(sum / n) : sum;
}

}  // namespace net_test
