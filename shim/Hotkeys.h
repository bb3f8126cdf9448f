#pragma once

// Hotkeys: the configured key combinations, read by polling the keyboard state at frame ends.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

struct _XDisplay;

namespace nprgl {

// As MangoHud does: XQueryKeymap on the program's display at each frame end, so the program's
// own input (its event queue) is untouched. Xlib's functions are looked up in the process
// (a GLX program has libX11 loaded); without them there are no hotkeys, said once.
class Hotkeys {
public:
    enum Action : uint32_t {
        Toggle = 1u << 0,
        Cycle = 1u << 1,
        Screenshot = 1u << 2,
        Overlay = 1u << 3,
        Reload = 1u << 4,
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
    // The actions whose whole combination is down now (a round trip to the X server).
    uint32_t held() const;
    std::vector<Binding> mBindings;
    _XDisplay* mDisplay = nullptr;
    uint32_t mDown = 0; // actions whose combination was held at the last poll
};

} // namespace nprgl
