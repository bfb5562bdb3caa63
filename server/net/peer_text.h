// Text a peer sent (a scene name, a parameter name), made safe to repeat in a log line or a reply's
// error: at most `max_bytes` of it, control characters shown as '?', invalid UTF-8 as '?', and a cut
// made on a character boundary with the full length said. Without this a 60 kB scene name went into
// every refusal's log line and reply, and a newline in one could forge a log line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace net {

inline constexpr std::size_t kMaxEchoBytes = 64;
// Every control reply's error text is cut to this (the peer text in it already is to kMaxEchoBytes).
inline constexpr std::size_t kMaxErrorBytes = 512;

// `text` as is when it is short, printable, valid UTF-8; else the safe form described above, at most
// `max_bytes` in all, e.g. "aaaa...aaa... (60000 bytes)".
std::string echoText(std::string_view text, std::size_t max_bytes = kMaxEchoBytes);

}  // namespace net
