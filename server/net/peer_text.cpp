#include "net/peer_text.h"

#include <algorithm>

namespace net {
namespace {

// Length of the UTF-8 sequence starting at text[i], or 0 when it is not a valid one (overlong forms
// and surrogates included, as protobuf's own check refuses them).
std::size_t utf8Length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t n = 0;
  unsigned int code = 0;
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF) {
    n = 2;
    code = lead & 0x1F;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    n = 3;
    code = lead & 0x0F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    n = 4;
    code = lead & 0x07;
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  const bool overlong = (n == 3 && code < 0x800) || (n == 4 && code < 0x10000);
  const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
  if (overlong || surrogate || code > 0x10FFFF) return 0;
  return n;
}

}  // namespace

std::string echoText(std::string_view text, std::size_t max_bytes) {
  // Room for the suffix a cut needs, so the whole stays within max_bytes.
  const std::string suffix = "... (" + std::to_string(text.size()) + " bytes)";
  const std::size_t room = max_bytes > suffix.size() ? max_bytes - suffix.size() : 0;
  std::string out;
  out.reserve(std::min(text.size(), max_bytes));
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t n = utf8Length(text, i);
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (n == 0 || (n == 1 && (c < 0x20 || c == 0x7F))) {
      out += '?';
      i += 1;
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
    if (out.size() > max_bytes) break;
  }
  if (out.size() <= max_bytes && i == text.size()) return out;
  // Too long: keep whole characters that fit in `room`.
  std::size_t keep = 0;
  for (std::size_t k = 0; k < out.size();) {
    const std::size_t n = std::max<std::size_t>(1, utf8Length(out, k));
    if (k + n > room) break;
    k += n;
    keep = k;
  }
  out.resize(keep);
  return out + suffix;
}

}  // namespace net
