#pragma once

// KeyEvents: every key press and release, as it happens, on an X connection of nprgl's own.

#include <bitset>
#include <string>
#include <vector>

struct _XDisplay;

namespace nprgl {

// A tap shorter than a frame is up again before the next frame end, so a keymap read there
// misses it. XInput2's raw key events, selected on the root window of a second connection to
// the program's X server, see it: the program's own connection, windows, event masks and
// grabs are untouched (no grab is taken). libXi is opened (not linked) the way the hotkeys
// find Xlib; without it, or without XInput 2 on the server, open() says why and fails.
class KeyEvents {
public:
    struct Event {
        unsigned keycode = 0;
        bool down = false;
    };

    KeyEvents() = default;
    KeyEvents(const KeyEvents&) = delete;
    KeyEvents& operator=(const KeyEvents&) = delete;
    ~KeyEvents();

    // Connects to `display`'s server (again when it is another display). False with `why`.
    bool open(_XDisplay* display, std::string& why);
    bool openFor(_XDisplay* display) const { return mConnection && display == mOf; }
    // The keyboard now (a bit per key code); the events up to now are dropped.
    std::bitset<256> keymap();
    // The key events since the last call (or keymap()), oldest first: one round trip.
    std::vector<Event> take();

private:
    void close();

    _XDisplay* mConnection = nullptr; // ours
    _XDisplay* mOf = nullptr;         // the program's
    int mOpcode = 0;                  // XInputExtension's major opcode
};

} // namespace nprgl
