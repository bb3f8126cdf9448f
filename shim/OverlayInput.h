#pragma once

// OverlayInput: the pointer over a window, read by polling (the program's events untouched).

#include <X11/X.h>

struct _XDisplay;

namespace nprgl {

struct PointerState {
    bool inside = false;      // over the window (x, y valid)
    float x = 0.0f, y = 0.0f; // window pixels from its top left
    bool buttons[3] = {};     // left, right, middle
};

// XQueryPointer on the program's display at frame ends while the overlay is open, as the
// hotkeys read XQueryKeymap: the program's own event queue never sees us. Xlib's function is
// looked up in the process; without it the overlay shows but takes no input (said once).
class OverlayInput {
public:
    PointerState poll(_XDisplay* display, Window window, int width, int height) const;
    // The keyboard's state (XQueryKeymap): a bit per X key code. False without Xlib.
    bool pollKeys(_XDisplay* display, char keymap[32]) const;
    // The key code of a keysym (0: none on this keyboard), and the keysym a key code types
    // (shifted: its second level).
    unsigned keycode(_XDisplay* display, unsigned long keysym) const;
    unsigned long keysym(_XDisplay* display, unsigned keycode, bool shifted) const;
};

} // namespace nprgl
