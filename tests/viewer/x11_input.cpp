#include "x11_input.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XTest.h>

#include <stdexcept>

namespace viewer_test {

namespace {
Display* dpy(void* p) { return static_cast<Display*>(p); }
}  // namespace

X11Input::X11Input() {
  display_ = XOpenDisplay(nullptr);
  if (display_ == nullptr) throw std::runtime_error("cannot open the X display");
  int event_base = 0, error_base = 0, major = 0, minor = 0;
  if (!XTestQueryExtension(dpy(display_), &event_base, &error_base, &major, &minor)) {
    throw std::runtime_error("X server has no XTEST extension");
  }
}

X11Input::~X11Input() { XCloseDisplay(dpy(display_)); }

unsigned long X11Input::findWindow(const std::string& title) {
  Display* d = dpy(display_);
  Window root = DefaultRootWindow(d), parent = 0, *children = nullptr;
  unsigned int count = 0;
  Window found = 0;
  if (XQueryTree(d, root, &root, &parent, &children, &count) != 0) {
    for (unsigned int i = 0; i < count && found == 0; ++i) {
      char* name = nullptr;
      if (XFetchName(d, children[i], &name) != 0 && name != nullptr) {
        if (title == name) found = children[i];
        XFree(name);
      }
    }
    if (children != nullptr) XFree(children);
  }
  return found;
}

std::optional<std::pair<int, int>> X11Input::windowOrigin(const std::string& title) {
  Display* d = dpy(display_);
  const Window w = findWindow(title);
  if (w == 0) return std::nullopt;
  XWindowAttributes attributes;
  if (XGetWindowAttributes(d, w, &attributes) == 0 || attributes.map_state != IsViewable) return std::nullopt;
  int x = 0, y = 0;
  Window child = 0;
  XTranslateCoordinates(d, w, DefaultRootWindow(d), 0, 0, &x, &y, &child);
  return std::make_pair(x, y);
}

void X11Input::movePointer(int root_x, int root_y) {
  XTestFakeMotionEvent(dpy(display_), -1, root_x, root_y, CurrentTime);
  XSync(dpy(display_), False);
}

void X11Input::button(int number, bool down) {
  XTestFakeButtonEvent(dpy(display_), static_cast<unsigned>(number), down ? True : False, CurrentTime);
  XSync(dpy(display_), False);
}

void X11Input::key(const char* keysym_name) {
  Display* d = dpy(display_);
  const KeyCode code = XKeysymToKeycode(d, XStringToKeysym(keysym_name));
  XTestFakeKeyEvent(d, code, True, CurrentTime);
  XTestFakeKeyEvent(d, code, False, CurrentTime);
  XSync(d, False);
}

void X11Input::focus(const std::string& title) {
  const Window w = findWindow(title);
  if (w != 0) XSetInputFocus(dpy(display_), w, RevertToPointerRoot, CurrentTime);
  XSync(dpy(display_), False);
}

}  // namespace viewer_test
