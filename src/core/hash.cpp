#include "core/hash.h"

#include <cstdio>

namespace hipr {

std::string Hasher::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(m_state));
  return text;
}

}  // namespace hipr
