// End to end: every kind of context a program can make (GL compatibility and core profiles,
// OpenGL ES 1/2/3 through GLX and EGL, OSMesa) under nprgl: the program's glGetError answers
// what it answers natively after each of its calls (nothing nprgl raised, and the program's
// own errors kept through nprgl's frame ends), its state reads back the same, and a context
// nprgl cannot style is passed through, pixel for pixel, and said so. Recorded too.

#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace nprgl::test;

namespace {

struct Kind {
    const char* name;
    bool stylable; // GL 3.0 compatibility or newer: the styles draw it
};

const Kind kKinds[] = {
    {"glx-compat", true}, {"glx-core", false},   {"glx-es2", false},
    {"glx-es3", false},   {"egl-compat", true},  {"egl-core", false},
    {"egl-es1", false},   {"egl-es2", false},    {"egl-es3", false},
    {"osmesa-compat", true}, {"osmesa-core", false},
};

void PrintTo(const Kind& kind, std::ostream* os) { *os << kind.name; }

std::vector<std::string> probe(const std::string& kind)
{
    const bool osmesa = kind.rfind("osmesa-", 0) == 0;
    return {binDir() + (osmesa ? "/probe_contexts_osmesa" : "/probe_contexts"), kind};
}

// A run without configuration files of the user's (a file would start the compositor).
std::map<std::string, std::string> cleanEnv(const std::string& name)
{
    return {{"XDG_CONFIG_HOME", freshDir(name)}, {"NPRGL_CONFIG_FILE", ""}};
}

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

bool isPixels(const std::string& line) { return line.find(": pixels ") != std::string::npos; }

size_t count(const std::string& text, const std::string& what)
{
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

class ContextKinds : public ::testing::TestWithParam<std::tuple<Kind, std::string>> {};

std::string caseName(const ::testing::TestParamInfo<std::tuple<Kind, std::string>>& info)
{
    std::string name = std::string(std::get<0>(info.param).name) + "_" +
                       (std::get<1>(info.param).empty() ? "default" : std::get<1>(info.param));
    for (char& c : name) {
        if (c == '-') c = '_';
    }
    return name;
}

} // namespace

TEST_P(ContextKinds, NoGlErrorAndNoStateOfNprgls)
{
    const auto& [kind, style] = GetParam();
    const std::string name = kind.name;
    if (name.rfind("glx-", 0) == 0) {
        const char* d = std::getenv("DISPLAY");
        ASSERT_TRUE(d && *d) << "no DISPLAY: run the tests through scripts/test.sh (Xvfb)";
    }
    ProcessResult native = runProcess(probe(name), cleanEnv("contexts_native"));
    if (native.exitCode == 3 && name == "egl-es1") {
        GTEST_SKIP() << "the driver offers no OpenGL ES 1 context: " << native.err;
    }
    ASSERT_EQ(native.exitCode, 0) << native.err;
    ASSERT_NE(native.out.find("unexpected errors: 0"), std::string::npos) << native.out;

    // "record": recorded to a file, unstyled (the recorder asks the driver about arrays,
    // buffers and the pixel store of every context kind).
    // "screenshot": unstyled, frames 2 and 3 written as PNGs (read back from the program's
    // context, its pixel store and bindings put back).
    std::vector<std::string> nprgl = {nprglCommand()};
    const std::string shots = freshDir("contexts_shots");
    if (style == "screenshot") {
        nprgl.insert(nprgl.end(), {"--style", "none", "--screenshot",
                                   "frames=2,3;dir=" + shots});
    } else if (style == "record") {
        nprgl.insert(nprgl.end(), {"record", "-o", freshDir("contexts_record") + "/probe.nprgl",
                                   "--style", "none"});
    } else if (!style.empty()) {
        nprgl.insert(nprgl.end(), {"--style", style});
    }
    ProcessResult r = runProcess(under(nprgl, probe(name)), cleanEnv("contexts_nprgl"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("nprgl: error"), std::string::npos) << r.err;
    // Every glGetError answer and every piece of state as natively (the probe prints each
    // answer that is not GL's, and its state at the end); the pixels too where nothing styles
    // them.
    const bool styled = kind.stylable && style.empty();
    std::string expected, seen;
    size_t restyled = 0;
    const std::vector<std::string> n = lines(native.out), s = lines(r.out);
    for (size_t i = 0; i < n.size(); ++i) {
        if (!styled || !isPixels(n[i])) expected += n[i] + "\n";
    }
    for (size_t i = 0; i < s.size(); ++i) {
        if (!styled || !isPixels(s[i])) seen += s[i] + "\n";
        else restyled += i >= n.size() || s[i] != n[i];
    }
    EXPECT_EQ(seen, expected) << r.err;
    if (styled) {
        // The style did draw the frames (the checks above pass for a style that draws nothing).
        EXPECT_GT(restyled, 0u) << r.out;
        return;
    }
    if (style == "screenshot") {
        size_t pictures = 0;
        for (const auto& entry : std::filesystem::directory_iterator(shots)) {
            pictures += entry.path().extension() == ".png";
        }
        EXPECT_EQ(pictures, 2u) << r.err;
    }
    if (!style.empty()) return;
    // A context nprgl cannot style is passed through and said so, once.
    EXPECT_EQ(count(r.err, "passthrough"), 1u) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Kinds, ContextKinds,
                         ::testing::Combine(::testing::ValuesIn(kKinds),
                                            ::testing::Values(std::string(), "none", "record",
                                                              "screenshot")),
                         caseName);

// Programs of Debian's mesa-utils that make every kind of context they can (glxinfo: core,
// compatibility and OpenGL ES through GLX; es2_info: OpenGL ES through EGL on X11), and say
// so when a GL error is left for them (glxinfo's "Warning: GL error 0x500" on its ES profile).
TEST(ContextTools, MesaUtilsSeeNoGlErrorOfNprgls)
{
    const char* d = std::getenv("DISPLAY");
    ASSERT_TRUE(d && *d) << "no DISPLAY: run the tests through scripts/test.sh (Xvfb)";
    const std::vector<std::vector<std::string>> programs = {
        {"glxinfo", "-B"}, {"es2_info"}};
    for (const auto& program : programs) {
        ProcessResult native = runProcess(program, cleanEnv("tools_native"));
        ASSERT_EQ(native.exitCode, 0) << program[0] << " (mesa-utils): " << native.err;
        for (const std::string style : {"none", "toon"}) {
            ProcessResult r = runProcess(under({nprglCommand(), "--style", style}, program),
                                         cleanEnv("tools_nprgl"));
            ASSERT_EQ(r.exitCode, 0) << program[0] << ": " << r.err;
            EXPECT_EQ(count(r.err, "GL error"), count(native.err, "GL error"))
                << program[0] << " --style " << style << ": " << r.err;
            EXPECT_EQ(r.out, native.out) << program[0] << " --style " << style;
        }
    }
}
