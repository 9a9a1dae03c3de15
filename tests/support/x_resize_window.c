/* Test helper: resizes the X11 top-level windows whose title starts with argv[1] to argv[2] x
   argv[3], as a user dragging the border would. Exit 1 when none is (yet) mapped. */
#include <X11/Xlib.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char** argv) {
  if (argc != 4) return 2;
  Display* display = XOpenDisplay(NULL);
  if (display == NULL) return 2;
  Window root, parent, *children = NULL;
  unsigned count = 0;
  int found = 0;
  XQueryTree(display, DefaultRootWindow(display), &root, &parent, &children, &count);
  for (unsigned i = 0; i < count; ++i) {
    char* name = NULL;
    if (XFetchName(display, children[i], &name) && name != NULL && strncmp(name, argv[1], strlen(argv[1])) == 0) {
      XResizeWindow(display, children[i], (unsigned)atoi(argv[2]), (unsigned)atoi(argv[3]));
      found = 1;
    }
    if (name != NULL) XFree(name);
  }
  if (children != NULL) XFree(children);
  XFlush(display);
  XCloseDisplay(display);
  return found ? 0 : 1;
}
