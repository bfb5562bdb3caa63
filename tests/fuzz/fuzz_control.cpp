// The server's control request check (server/net/input_validation.h).
#include <cstddef>
#include <cstdint>

#include "fuzz_check.h"
#include "net/input_validation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gsph::v1::Control control;
  if (!net::parseControl(data, size, control).empty()) return 0;
  FUZZ_CHECK(control.protocol_version() == gsph::v1::PROTOCOL_VERSION_CURRENT);
  FUZZ_CHECK(control.command_case() != gsph::v1::Control::COMMAND_NOT_SET);
  return 0;
}
