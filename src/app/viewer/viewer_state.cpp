#include "app/viewer/viewer_state.h"

#include "core/log.h"

namespace hipr::viewer {

namespace {
constexpr size_t kKeptMessages = 50;
}

void ViewerState::info(const std::string& text) {
  messages.push_back({text, false});
  ++message_count;
  if (messages.size() > kKeptMessages) messages.erase(messages.begin());
}

void ViewerState::error(const std::string& text) {
  messages.push_back({text, true});
  ++message_count;
  if (messages.size() > kKeptMessages) messages.erase(messages.begin());
  log::warn(text);
}

}  // namespace hipr::viewer
