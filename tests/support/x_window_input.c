/* Test helper: acts on the X11 top-level windows whose title starts with TITLE as a user would:
     x_window_input resize TITLE WIDTH HEIGHT   drags the border to a new size
     x_window_input key TITLE KEYSYM MS         holds a key (e.g. "w") for MS milliseconds
   Exit 1 when no such window is mapped yet (callers retry), 2 on bad use or no display. */
#include <X11/Xlib.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static Window findWindow(Display* display, const char* title) {
  Window root, parent, *children = NULL, found = 0;
  unsigned count = 0;
  XQueryTree(display, DefaultRootWindow(display), &root, &parent, &children, &count);
  for (unsigned i = 0; i < count && !found; ++i) {
    char* name = NULL;
    /* Only a viewable window: GLFW names its window before mapping it, and a key sent then
       is lost (the focus cannot be set on an unmapped window; on a loaded machine the gap
       between the two is long enough to hit). */
    XWindowAttributes attributes;
    if (XFetchName(display, children[i], &name) && name != NULL && strncmp(name, title, strlen(title)) == 0 &&
        XGetWindowAttributes(display, children[i], &attributes) && attributes.map_state == IsViewable) {
      found = children[i];
    }
    if (name != NULL) XFree(name);
  }
  if (children != NULL) XFree(children);
  return found;
}

static void sendKey(Display* display, Window window, int type, unsigned keycode) {
  XKeyEvent event;
  memset(&event, 0, sizeof event);
  event.type = type;
  event.display = display;
  event.window = window;
  event.root = DefaultRootWindow(display);
  event.same_screen = True;
  event.keycode = keycode;
  XSendEvent(display, window, True, type == KeyPress ? KeyPressMask : KeyReleaseMask, (XEvent*)&event);
  XFlush(display);
}

int main(int argc, char** argv) {
  if (argc != 5) return 2;
  Display* display = XOpenDisplay(NULL);
  if (display == NULL) return 2;
  Window window = findWindow(display, argv[2]);
  int status = window ? 0 : 1;
  if (window && strcmp(argv[1], "resize") == 0) {
    XResizeWindow(display, window, (unsigned)atoi(argv[3]), (unsigned)atoi(argv[4]));
    XFlush(display);
  } else if (window && strcmp(argv[1], "key") == 0) {
    unsigned keycode = XKeysymToKeycode(display, XStringToKeysym(argv[3]));
    XSetInputFocus(display, window, RevertToParent, CurrentTime);
    sendKey(display, window, KeyPress, keycode);
    usleep((useconds_t)atoi(argv[4]) * 1000u);
    sendKey(display, window, KeyRelease, keycode);
  } else if (window) {
    status = 2;
  }
  XCloseDisplay(display);
  return status;
}
