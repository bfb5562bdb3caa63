// Drives the X server the viewer runs on, as a user would: find the viewer's window, move the
// pointer, drag with a button, press a key (XTest). Used only by the tests.
#pragma once

#include <optional>
#include <string>

namespace viewer_test {

class X11Input {
 public:
  X11Input();  // opens $DISPLAY; throws when it cannot
  ~X11Input();
  X11Input(const X11Input&) = delete;
  X11Input& operator=(const X11Input&) = delete;

  // Top-left corner (root coordinates) of the top-level window titled `title`, if mapped.
  std::optional<std::pair<int, int>> windowOrigin(const std::string& title);
  void movePointer(int root_x, int root_y);
  void button(int number, bool down);
  void key(const char* keysym_name);  // press and release
  void focus(const std::string& title);

 private:
  unsigned long findWindow(const std::string& title);
  void* display_ = nullptr;
};

}  // namespace viewer_test
