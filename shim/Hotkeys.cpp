#include "shim/Hotkeys.h"

#include "common/Log.h"

#include <X11/Xlib.h>
#include <dlfcn.h>

#include <bit>
#include <string_view>
#include <utility>

namespace nprgl {

namespace {

struct Xlib {
    int (*queryKeymap)(Display*, char[32]) = nullptr;
    KeySym (*stringToKeysym)(const char*) = nullptr;
    KeyCode (*keysymToKeycode)(Display*, KeySym) = nullptr;
    bool ok() const { return queryKeymap && stringToKeysym && keysymToKeycode; }
};

const Xlib& xlib()
{
    static const Xlib x = [] {
        Xlib f;
        f.queryKeymap = reinterpret_cast<decltype(f.queryKeymap)>(dlsym(RTLD_DEFAULT, "XQueryKeymap"));
        f.stringToKeysym =
            reinterpret_cast<decltype(f.stringToKeysym)>(dlsym(RTLD_DEFAULT, "XStringToKeysym"));
        f.keysymToKeycode = reinterpret_cast<decltype(f.keysymToKeycode)>(
            dlsym(RTLD_DEFAULT, "XKeysymToKeycode"));
        if (!f.ok()) NPRGL_WARN("Xlib's keyboard functions are not in this process: no hotkeys");
        return f;
    }();
    return x;
}

uint32_t actionBit(const std::string& name)
{
    if (name == "toggle") return Hotkeys::Toggle;
    if (name == "cycle") return Hotkeys::Cycle;
    if (name == "screenshot") return Hotkeys::Screenshot;
    if (name == "overlay") return Hotkeys::Overlay;
    if (name == "reload") return Hotkeys::Reload;
    if (name == "video") return Hotkeys::Video;
    return 0;
}

} // namespace

void Hotkeys::bind(const std::map<std::string, std::string>& keys,
                   const std::map<std::string, std::string>& lines, _XDisplay* display)
{
    const std::vector<Binding> old = std::exchange(mBindings, {});
    const bool sameDisplay = display == mDisplay;
    mDisplay = display;
    const uint32_t wasDown = std::exchange(mDown, 0u);
    const Xlib& x = xlib();
    if (!display || !x.ok()) return;
    for (const auto& [action, combination] : keys) {
        const uint32_t bit = actionBit(action);
        if (!bit || combination == "none") continue;
        Binding binding;
        binding.action = bit;
        bool ok = true;
        std::string_view rest = combination;
        while (ok && !rest.empty()) {
            const size_t plus = rest.find('+');
            const std::string name(rest.substr(0, plus));
            rest = plus == std::string_view::npos ? std::string_view() : rest.substr(plus + 1);
            const KeySym sym = x.stringToKeysym(name.c_str());
            const KeyCode code = sym == NoSymbol ? 0 : x.keysymToKeycode(display, sym);
            if (code == 0) {
                const auto line = lines.find(action);
                const std::string where = line == lines.end() ? "" : line->second + ": ";
                NPRGL_ERROR("%s%s_key=%s: no key '%s' on this keyboard; %s is unbound",
                            where.c_str(), action.c_str(), combination.c_str(), name.c_str(),
                            action.c_str());
                ok = false;
            }
            binding.keycodes.push_back(code);
        }
        if (ok && !binding.keycodes.empty()) mBindings.push_back(std::move(binding));
    }
    openEvents(display);
    // A press is a combination going down: one held across a rebinding (a reload, the reload
    // key itself) is not pressed again. Kept as last polled where the combination is the
    // same, else as held now.
    uint32_t kept = 0;
    for (const Binding& b : mBindings) {
        for (const Binding& o : old) {
            if (sameDisplay && o.action == b.action && o.keycodes == b.keycodes) kept |= b.action;
        }
    }
    mDown = wasDown & kept;
    if (mBindings.size() != size_t(std::popcount(kept))) {
        // With key events mKeys is the keyboard as of the last event taken.
        if (!mEvents.openFor(display)) readKeymap();
        mDown |= held() & ~kept;
    }
}

void Hotkeys::openEvents(_XDisplay* display)
{
    if (mBindings.empty() || mNoEvents || mEvents.openFor(display)) return;
    std::string why;
    if (mEvents.open(display, why)) {
        mKeys = mEvents.keymap();
        return;
    }
    mNoEvents = true;
    static bool said = false;
    if (!said) {
        NPRGL_WARN("hotkeys: no key events (%s): the keyboard is read once a frame, and a key "
                   "tap shorter than a frame is missed",
                   why.c_str());
    }
    said = true;
}

void Hotkeys::readKeymap()
{
    char keymap[32] = {};
    xlib().queryKeymap(mDisplay, keymap);
    for (unsigned code = 0; code < 256; ++code)
        mKeys[code] = (keymap[code >> 3] >> (code & 7)) & 1;
}

uint32_t Hotkeys::held() const
{
    uint32_t down = 0;
    for (const Binding& b : mBindings) {
        bool all = true;
        for (uint8_t code : b.keycodes) all = all && mKeys[code];
        if (all) down |= b.action;
    }
    return down;
}

uint32_t Hotkeys::poll(_XDisplay* display)
{
    if (mBindings.empty() || display != mDisplay) return 0;
    if (!mEvents.openFor(display)) {
        readKeymap();
        const uint32_t down = held();
        const uint32_t pressed = down & ~mDown;
        mDown = down;
        return pressed;
    }
    // Each press that completes a combination counts, though it may be up again by now.
    uint32_t pressed = 0;
    for (const KeyEvents::Event& e : mEvents.take()) {
        mKeys[e.keycode] = e.down;
        const uint32_t down = held();
        if (e.down) pressed |= down & ~mDown;
        mDown = down;
    }
    return pressed;
}

} // namespace nprgl
