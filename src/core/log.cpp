#include "core/log.h"

#include <atomic>
#include <cstdint>
#include <cstdio>

namespace hipr::log {
namespace {
std::atomic<bool> g_quiet{false};

// Bytes of a valid UTF-8 sequence starting at `i` (1-4), or 0 when it is not one.
size_t utf8_sequence(std::string_view s, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  size_t length = lead < 0x80           ? 1
                  : (lead >> 5) == 0x6  ? 2
                  : (lead >> 4) == 0xe  ? 3
                  : (lead >> 3) == 0x1e ? 4
                                        : 0;
  if (length == 0 || i + length > s.size()) return 0;
  for (size_t k = 1; k < length; ++k)
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
  uint32_t code = length == 1 ? lead : lead & (0xff >> (length + 1));
  for (size_t k = 1; k < length; ++k) code = (code << 6) | (byte(i + k) & 0x3f);
  const uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};  // overlong forms are invalid
  if (code < least[length] || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return length;
}

}  // namespace

std::string printable_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  char escaped[8];
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const size_t length = utf8_sequence(text, i);
    if (c == '\n' || c == '\r' || c == '\t') {
      out += ' ';
      i += 1;
    } else if (length == 0 || c < 0x20 || c == 0x7f) {
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
      i += 1;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

void warn(std::string_view message) {
  std::fprintf(stderr, "hipr: warning: %s\n", printable_line(message).c_str());
}

void info(std::string_view message) {
  if (!g_quiet) std::fprintf(stderr, "hipr: %s\n", printable_line(message).c_str());
}

void set_quiet(bool quiet) { g_quiet = quiet; }

}  // namespace hipr::log
