#include "shim/KeyEvents.h"

#include "shim/DlopenHook.h"

#include <X11/Xlib.h>
#include <X11/extensions/XInput2.h>
#include <dlfcn.h>
#include <mutex>

#include <type_traits>

namespace nprgl {

namespace {

// Xlib's and libXi's functions, from libXi (which brings libX11 when the program has not).
struct Xi {
    Display* (*openDisplay)(const char*) = nullptr;
    int (*closeDisplay)(Display*) = nullptr;
    char* (*displayString)(Display*) = nullptr;
    Window (*rootWindow)(Display*) = nullptr;
    Bool (*queryExtension)(Display*, const char*, int*, int*, int*) = nullptr;
    int (*sync)(Display*, Bool) = nullptr;
    int (*eventsQueued)(Display*, int) = nullptr;
    int (*nextEvent)(Display*, XEvent*) = nullptr;
    int (*queryKeymap)(Display*, char[32]) = nullptr;
    Bool (*getEventData)(Display*, XGenericEventCookie*) = nullptr;
    void (*freeEventData)(Display*, XGenericEventCookie*) = nullptr;
    Status (*queryVersion)(Display*, int*, int*) = nullptr;
    int (*selectEvents)(Display*, Window, XIEventMask*, int) = nullptr;
    bool ok = false;
};

const Xi& xi()
{
    static const Xi x = [] {
        Xi f;
        void* lib = realDlopen("libXi.so.6", RTLD_NOW | RTLD_LOCAL);
        if (!lib) return f;
        auto get = [&](auto& fn, const char* name) {
            fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(lib, name));
            return fn != nullptr;
        };
        f.ok = get(f.openDisplay, "XOpenDisplay") && get(f.closeDisplay, "XCloseDisplay") &&
               get(f.displayString, "XDisplayString") && get(f.rootWindow, "XDefaultRootWindow") &&
               get(f.queryExtension, "XQueryExtension") && get(f.sync, "XSync") &&
               get(f.eventsQueued, "XEventsQueued") && get(f.nextEvent, "XNextEvent") &&
               get(f.queryKeymap, "XQueryKeymap") && get(f.getEventData, "XGetEventData") &&
               get(f.freeEventData, "XFreeEventData") && get(f.queryVersion, "XIQueryVersion") &&
               get(f.selectEvents, "XISelectEvents");
        return f;
    }();
    return x;
}

} // namespace

KeyEvents::~KeyEvents() { close(); }

void KeyEvents::close()
{
    if (mConnection) xi().closeDisplay(mConnection);
    mConnection = nullptr;
    mOf = nullptr;
}

bool KeyEvents::open(_XDisplay* display, std::string& why)
{
    close();
    const Xi& x = xi();
    if (!x.ok) {
        why = "libXi.so.6 is not installed";
        return false;
    }
    // libXau names the authority file in a static buffer: two contexts' threads opening their
    // connections at once race on it (ThreadSanitizer saw it). Once per context, not per call.
    static std::mutex opening;
    Display* own = nullptr;
    {
        std::lock_guard lock(opening);
        own = x.openDisplay(x.displayString(display));
    }
    if (!own) {
        why = "cannot open a second connection to the display";
        return false;
    }
    // Asked first: XIQueryVersion on a server without the extension would raise an X error
    // (seen by the program's error handler, which is process-wide).
    int opcode = 0, event = 0, error = 0;
    int major = 2, minor = 2; // 2.1 and later: raw events come during grabs too
    if (!x.queryExtension(own, "XInputExtension", &opcode, &event, &error) ||
        x.queryVersion(own, &major, &minor) != Success || major < 2) {
        x.closeDisplay(own);
        why = "the X server has no XInput 2";
        return false;
    }
    unsigned char bits[XIMaskLen(XI_LASTEVENT)] = {};
    XISetMask(bits, XI_RawKeyPress);
    XISetMask(bits, XI_RawKeyRelease);
    XIEventMask mask{XIAllMasterDevices, int(sizeof bits), bits};
    x.selectEvents(own, x.rootWindow(own), &mask, 1);
    x.sync(own, False);
    mConnection = own;
    mOf = display;
    mOpcode = opcode;
    return true;
}

std::bitset<256> KeyEvents::keymap()
{
    std::bitset<256> keys;
    if (!mConnection) return keys;
    const Xi& x = xi();
    char map[32] = {};
    x.queryKeymap(mConnection, map);
    // Events read while waiting for the reply came before it: the map has them already.
    XEvent event;
    while (x.eventsQueued(mConnection, QueuedAlready) > 0) {
        x.nextEvent(mConnection, &event);
    }
    for (unsigned code = 0; code < 256; ++code)
        keys[code] = (map[code >> 3] >> (code & 7)) & 1;
    return keys;
}

std::vector<KeyEvents::Event> KeyEvents::take()
{
    std::vector<Event> events;
    if (!mConnection) return events;
    const Xi& x = xi();
    // A round trip: every event the server made before it is in the queue after it.
    x.sync(mConnection, False);
    XEvent event;
    while (x.eventsQueued(mConnection, QueuedAlready) > 0) {
        x.nextEvent(mConnection, &event);
        XGenericEventCookie* cookie = &event.xcookie;
        if (cookie->type != GenericEvent || cookie->extension != mOpcode ||
            !x.getEventData(mConnection, cookie)) {
            continue;
        }
        const auto* raw = static_cast<const XIRawEvent*>(cookie->data);
        const bool down = cookie->evtype == XI_RawKeyPress;
        if ((down || cookie->evtype == XI_RawKeyRelease) && raw->detail > 0 && raw->detail < 256) {
            events.push_back({unsigned(raw->detail), down});
        }
        x.freeEventData(mConnection, cookie);
    }
    return events;
}

} // namespace nprgl
