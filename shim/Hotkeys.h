#pragma once

// Hotkeys: the configured key combinations, from key events (or the keyboard state at frame ends).

#include "shim/KeyEvents.h"

#include <bitset>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

struct _XDisplay;

namespace nprgl {

// Key events of a connection of nprgl's own (KeyEvents), taken at each frame end, so a tap
// between two frame ends counts; the program's own input (its event queue) is untouched.
// Without XInput 2 (said once), as MangoHud does: XQueryKeymap on the program's display at
// each frame end, which misses a tap shorter than a frame. Xlib's functions are looked up in
// the process (a GLX program has libX11 loaded); without them there are no hotkeys, said once.
class Hotkeys {
public:
    enum Action : uint32_t {
        Toggle = 1u << 0,
        Cycle = 1u << 1,
        Screenshot = 1u << 2,
        Overlay = 1u << 3,
        Reload = 1u << 4,
        Video = 1u << 5,
    };

    // Binds action names ("toggle", ...) to combinations ("Shift_R+F9"; "none" unbinds) on
    // this display. A combination naming an unknown key is reported (at its "file:line" of
    // `lines`, when there) and left unbound. One held while it is bound again (a reload)
    // does not count as pressed.
    void bind(const std::map<std::string, std::string>& keys,
              const std::map<std::string, std::string>& lines, _XDisplay* display);
    bool boundTo(_XDisplay* display) const { return display && display == mDisplay; }
    // The actions whose whole combination went down since the last poll.
    uint32_t poll(_XDisplay* display);

private:
    struct Binding {
        uint32_t action = 0;
        std::vector<uint8_t> keycodes;
    };
    // The actions whose whole combination is down in mKeys.
    uint32_t held() const;
    // mKeys from the keymap of the program's display (no key events).
    void readKeymap();
    // Key events for `display`, once per display: said once where there are none.
    void openEvents(_XDisplay* display);
    std::vector<Binding> mBindings;
    _XDisplay* mDisplay = nullptr;
    uint32_t mDown = 0;     // actions whose combination was held after the last key seen
    std::bitset<256> mKeys; // the keys down, as last seen
    KeyEvents mEvents;
    bool mNoEvents = false; // XInput 2 is missing: polled
};

} // namespace nprgl
