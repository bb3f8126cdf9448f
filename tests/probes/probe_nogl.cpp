// Links no GL library and finds GL only through whatever is preloaded: stands in for a
// machine where the real libGL is missing.
#include <cstdio>
#include <dlfcn.h>

int main()
{
    using GetString = const unsigned char* (*)(unsigned);
    using Clear = void (*)(unsigned);
    auto getString = reinterpret_cast<GetString>(dlsym(RTLD_DEFAULT, "glGetString"));
    auto clear = reinterpret_cast<Clear>(dlsym(RTLD_DEFAULT, "glClear"));
    if (!getString || !clear) {
        std::printf("no GL symbols\n");
        return 0;
    }
    clear(0x4000);
    std::printf("glGetString=%s\n", getString(0x1F02) ? "set" : "null");
    clear(0x4000);
    return 0;
}
