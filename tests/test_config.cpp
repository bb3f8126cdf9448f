// Configuration files (shim/Config, shim/ConfigFile, shim/ConfigWatcher): where they are read
// from, their precedence, bad lines, and a changed file restyling a running program.

#include "common/PngImage.h"
#include "shim/ConfigFile.h"
#include "tests/support/Process.h"
#include "tests/support/ReloadFrames.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <iterator>

using namespace nprgl;
using namespace nprgl::test;

namespace {

std::string probe() { return binDir() + "/probe_reload"; }

void writeFile(const std::string& path, const std::string& text)
{
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path) << text;
}

// The environment of a run that reads its files from `home` only.
std::map<std::string, std::string> filesIn(const std::string& home)
{
    return {{"XDG_CONFIG_HOME", home}, {"NPRGL_CONFIG_FILE", ""}, {"NPRGL_STYLE", ""},
            {"NPRGL_CONFIG", ""}, {"NPRGL_PRESET", ""}};
}

} // namespace

TEST(ConfigFile, ABadLineIsNamedAndSkippedAndTheRestApplies)
{
    const ConfigFile f = ConfigFile::parse("# look\n"
                                           "style=toon+edges\n"
                                           "toon.nonsense=1\n"
                                           "no equals sign\n"
                                           "toon.diffuse_threshold=0.3   # trailing comment\n"
                                           "toggle_key=Shift_R+F6\n"
                                           "jump_key=F1\n"
                                           "log_level=loud\n"
                                           "cycle=toon, preset:pencil, nostyle\n"
                                           "screenshot_dir=/tmp/shots\n",
                                           "my.conf");
    EXPECT_EQ(f.chain, "toon+edges");
    EXPECT_EQ(f.config, "toon.diffuse_threshold=0.3");
    EXPECT_EQ(f.keys.at("toggle"), "Shift_R+F6");
    EXPECT_EQ(f.keys.count("jump"), 0u);
    EXPECT_EQ(f.screenshotDir, "/tmp/shots");
    EXPECT_TRUE(f.cycle.empty()) << "a cycle list with an unknown style is refused whole";
    ASSERT_EQ(f.errors.size(), 5u);
    EXPECT_EQ(f.errors[0].rfind("my.conf:3: ", 0), 0u) << f.errors[0];
    EXPECT_EQ(f.errors[1].rfind("my.conf:4: ", 0), 0u) << f.errors[1];
    EXPECT_EQ(f.errors[2].rfind("my.conf:7: ", 0), 0u) << f.errors[2];
    EXPECT_EQ(f.errors[3].rfind("my.conf:8: ", 0), 0u) << f.errors[3];
    EXPECT_EQ(f.errors[4].rfind("my.conf:9: ", 0), 0u) << f.errors[4];
}

// State rules: one state a line; an unknown one is named and skipped.
TEST(ConfigFile, StateRulesNameTheirStates)
{
    const ConfigFile f = ConfigFile::parse("leave_state=translucent\n"
                                           "leave_state=glowing\n"
                                           "leave_state=backdrop\n",
                                           "rules.conf");
    EXPECT_EQ(f.rules.states, uint32_t(kLeaveTranslucent | kLeaveBackdrop));
    ASSERT_EQ(f.errors.size(), 1u);
    EXPECT_EQ(f.errors[0].rfind("rules.conf:2: leave_state: 'glowing'", 0), 0u) << f.errors[0];
}

// Saving a look replaces the old rules with the new ones (texture and state), keeps the other
// lines, and what it writes reads back as the same rules.
TEST(ConfigFile, SavedRulesReadBackAndReplaceTheOldOnes)
{
    const std::string path = freshDir("write_look") + "/p.conf";
    {
        std::ofstream out(path);
        out << "# mine\nleave_state=cutout\nleave_texture=00000000000000aa\nlog_level=warn\n";
    }
    LeaveRules rules;
    rules.textures = {0x1234, 0xbeef};
    rules.states = kLeaveDecal | kLeaveTranslucent;
    std::string error;
    ASSERT_TRUE(ConfigFile::writeLook(path, "toon", "toon.diffuse_threshold=0.7", rules, error))
        << error;
    const ConfigFile f = ConfigFile::read(path);
    EXPECT_TRUE(f.errors.empty());
    EXPECT_EQ(f.rules, rules);
    EXPECT_EQ(f.logLevel, "warn");
    EXPECT_EQ(f.chain, "toon");
}

// A look the next start would skip (two shading styles) is not written: the file keeps what
// it had, and the error says why.
TEST(ConfigFile, ALookTheRegistryRefusesIsNotSaved)
{
    const std::string path = freshDir("write_bad_look") + "/p.conf";
    std::ofstream(path) << "style=toon+edges\n";
    std::string error;
    EXPECT_FALSE(ConfigFile::writeLook(path, "toon+paper+edges+halftone", "", {}, error));
    EXPECT_NE(error.find("a chain takes one shading style"), std::string::npos) << error;
    EXPECT_EQ(ConfigFile::read(path).chain, "toon+edges");
}

// A file that cannot be written says why (here its temporary name is taken by a folder).
TEST(ConfigFile, AFailedSaveSaysWhy)
{
    const std::string path = freshDir("write_blocked") + "/p.conf";
    std::filesystem::create_directories(path + ".nprgl-new");
    std::string error;
    EXPECT_FALSE(ConfigFile::writeLook(path, "toon", "", {}, error));
    EXPECT_NE(error.find(".nprgl-new: Is a directory"), std::string::npos) << error;
}

TEST(ConfigFile, APresetLineGivesItsChainAndValuesUnderTheFilesOwn)
{
    const ConfigFile f = ConfigFile::parse("paper.grain=0.5\npreset=pencil\n", "p.conf");
    EXPECT_TRUE(f.errors.empty());
    EXPECT_EQ(f.chain, "pencil+paper");
    // The file's own value comes last, so it wins over the preset's paper.grain.
    const size_t own = f.config.rfind("paper.grain=0.5");
    ASSERT_NE(own, std::string::npos) << f.config;
    EXPECT_EQ(own + std::string("paper.grain=0.5").size(), f.config.size()) << f.config;
}

// Command line > environment > the program's file > the global file > the default.
TEST(Config, TheProgramsFileWinsOverTheGlobalOneAndTheCommandLineOverBoth)
{
    const std::string home = freshDir("config_precedence"), out = freshDir("config_out");
    writeFile(home + "/nprgl/nprgl.conf", "style=toon\nbogus\n");
    const std::vector<std::string> program = {probe(), "--frames", "1", "--save-dir", out};
    ProcessResult global = runProcess(under({nprglCommand()}, program), filesIn(home));
    ASSERT_EQ(global.exitCode, 0) << global.err;
    EXPECT_NE(global.err.find("probe_reload: style toon\n"), std::string::npos) << global.err;
    EXPECT_NE(global.err.find("nprgl.conf:2: expected key=value"), std::string::npos)
        << global.err;

    writeFile(home + "/nprgl/probe_reload.conf", "style=halftone\n");
    ProcessResult own = runProcess(under({nprglCommand()}, program), filesIn(home));
    ASSERT_EQ(own.exitCode, 0) << own.err;
    EXPECT_NE(own.err.find("probe_reload: style halftone\n"), std::string::npos) << own.err;

    ProcessResult command =
        runProcess(under({nprglCommand(), "--style", "toon+edges"}, program), filesIn(home));
    ASSERT_EQ(command.exitCode, 0) << command.err;
    EXPECT_NE(command.err.find("probe_reload: style toon+edges\n"), std::string::npos)
        << command.err;

    // NPRGL_CONFIG_FILE: that file alone.
    writeFile(home + "/elsewhere.conf", "style=textured\n");
    auto env = filesIn(home);
    env["NPRGL_CONFIG_FILE"] = home + "/elsewhere.conf";
    ProcessResult named = runProcess(under({nprglCommand()}, program), env);
    ASSERT_EQ(named.exitCode, 0) << named.err;
    EXPECT_NE(named.err.find("probe_reload: style textured\n"), std::string::npos) << named.err;
}

// The probe rewrites the file after frame 2 (style none -> toon+edges) and after frame 4
// (back to none). A change is noticed at the next frame end and runs from the frame after:
// frames 1-3 are the program's own picture, 4-5 styled, 6 the program's again. One line
// says each change; nothing restarts.
TEST(Config, AChangedFileRestylesTheRunningProgram)
{
    const std::string home = freshDir("config_reload"), native = freshDir("reload_native"),
                      live = freshDir("reload_live"), styled = freshDir("reload_styled");
    const std::string file = home + "/nprgl/nprgl.conf";
    writeFile(file, "style=none\n");
    ProcessResult n = runProcess({probe(), "--frames", "6", "--save-dir", native});
    ASSERT_EQ(n.exitCode, 0) << n.err;
    ProcessResult s =
        runProcess(under({nprglCommand(), "--style", "toon+edges"},
                         {probe(), "--frames", "6", "--save-dir", styled}),
                   filesIn(freshDir("config_none")));
    ASSERT_EQ(s.exitCode, 0) << s.err;
    ProcessResult r = runProcess(
        under({nprglCommand()}, {probe(), "--frames", "6", "--save-dir", live, "--file", file,
                                 "--at", "2", "--text", "style=toon+edges", "--at", "4",
                                 "--text", "style=none"}),
        filesIn(home));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, n.out);
    for (int f : {1, 2, 3, 6}) {
        EXPECT_EQ(differing(frame(native, f), frame(live, f)), 0) << "frame " << f;
    }
    for (int f : {4, 5}) {
        EXPECT_GT(differing(frame(native, f), frame(live, f)), 200) << "frame " << f
                                                                      << " not restyled";
        // As if it had run toon+edges from the start: nothing of the frames before.
        EXPECT_EQ(differing(frame(styled, f), frame(live, f)), 0) << "frame " << f;
    }
    EXPECT_NE(r.err.find("configuration changed: style now toon+edges"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("configuration changed: style now none"), std::string::npos) << r.err;
}

// Occurrences of `text` in `log`.
size_t countOf(const std::string& log, const std::string& text)
{
    size_t n = 0;
    for (size_t at = log.find(text); at != std::string::npos; at = log.find(text, at + 1))
        ++n;
    return n;
}

// The config folder (and XDG_CONFIG_HOME itself) is missing at start-up, as for most users:
// the default look runs. Made after frame 2 with style=none in it, frames 4-6 are the
// program's own; removed after frame 5, the default look from frame 7; made again after
// frame 7, the program's own from frame 9. One line says each change; the file written again
// after frame 8 with what it had is no change and says nothing.
TEST(Config, AConfigFolderMadeOrRemovedWhileRunningIsFollowed)
{
    const std::string home = freshDir("config_folder"), native = freshDir("folder_native"),
                      styled = freshDir("folder_styled"), live = freshDir("folder_live");
    const std::string file = home + "/config/nprgl/nprgl.conf";
    ProcessResult n = runProcess({probe(), "--frames", "9", "--save-dir", native});
    ASSERT_EQ(n.exitCode, 0) << n.err;
    ProcessResult s =
        runProcess(under({nprglCommand()}, {probe(), "--frames", "9", "--save-dir", styled}),
                   filesIn(home + "/none"));
    ASSERT_EQ(s.exitCode, 0) << s.err;
    ProcessResult r = runProcess(
        under({nprglCommand()},
              {probe(), "--frames", "9",         "--save-dir", live,         "--file",
               file,    "--at",     "2",         "--text",     "style=none", "--remove-folder",
               "5",     "--at",     "7",         "--text",     "style=none", "--at",
               "8",     "--text",   "style=none"}),
        filesIn(home + "/config"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_GT(differing(frame(native, 1), frame(styled, 1)), 200) << "the default look is none";
    for (int f : {1, 2, 3, 7, 8}) {
        EXPECT_EQ(differing(frame(styled, f), frame(live, f)), 0) << "frame " << f;
    }
    for (int f : {4, 5, 6, 9}) {
        EXPECT_EQ(differing(frame(native, f), frame(live, f)), 0) << "frame " << f;
    }
    EXPECT_EQ(countOf(r.err, "configuration changed: style now none"), 2u) << r.err;
    EXPECT_EQ(countOf(r.err, "configuration changed: style now toon+paper+edges"), 1u) << r.err;
}

namespace {

std::string hotkeyProbe() { return binDir() + "/probe_hotkeys"; }

// probe_hotkeys under nprgl with `args` (its own after the nprgl options), screenshots of
// `frames` into a fresh directory; returns the directory.
std::string runHotkeys(const std::string& name, const std::vector<std::string>& nprgl,
                       const std::vector<std::string>& args, const std::string& frames,
                       std::map<std::string, std::string> env = {})
{
    const std::string dir = freshDir(name);
    env["NPRGL_SCREENSHOT"] = "frames=" + frames + ";dir=" + dir;
    if (!env.count("NPRGL_CONFIG_FILE")) env["NPRGL_CONFIG_FILE"] = "";
    if (!env.count("XDG_CONFIG_HOME")) env["XDG_CONFIG_HOME"] = freshDir(name + "_home");
    std::vector<std::string> program = {hotkeyProbe()};
    program.insert(program.end(), args.begin(), args.end());
    ProcessResult r = runProcess(under(nprgl, program), env);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "ok\n");
    std::ofstream(dir + "/stderr.txt") << r.err;
    return dir;
}

std::string stderrOf(const std::string& dir)
{
    std::ifstream in(dir + "/stderr.txt");
    return {std::istreambuf_iterator<char>(in), {}};
}

PngImage shot(const std::string& dir, int frame)
{
    PngImage image;
    std::string error;
    EXPECT_TRUE(PngImage::read(dir + "/probe_hotkeys_" + std::to_string(frame) + ".png", image,
                               error))
        << error;
    return image;
}

} // namespace

// The toggle key (Shift_R+F9) held during frame 3 turns styling off from frame 4, held again
// during frame 5 on from frame 6: frame 4 is the program's own picture, 2 and 6 are styled.
TEST(Hotkeys, TheToggleKeyShowsTheProgramsOwnPictureAndBack)
{
    const std::vector<std::string> nprgl = {nprglCommand(), "--style", "toon+edges"};
    const std::string native =
        runHotkeys("keys_native", {nprglCommand(), "--style", "none"}, {"--frames", "6"},
                   "2,4,6");
    const std::string styled = runHotkeys("keys_styled", nprgl, {"--frames", "6"}, "2,4,6");
    const std::string keyed = runHotkeys("keys_toggle", nprgl,
                                         {"--frames", "6", "--press", "3", "Shift_R+F9",
                                          "--press", "5", "Shift_R+F9"},
                                         "2,4,6");
    EXPECT_GT(differing(shot(native, 4), shot(styled, 4)), 200) << "the style changes nothing";
    EXPECT_EQ(differing(shot(keyed, 2), shot(styled, 2)), 0);
    EXPECT_EQ(differing(shot(keyed, 4), shot(native, 4)), 0) << "styling not off";
    EXPECT_EQ(differing(shot(keyed, 6), shot(styled, 6)), 0) << "styling not back on";
}

// A tap that goes down and up again between two frame ends (a frame is slow under heavy
// styles, a tap is short) acts as a longer press does: frame 4 is the program's own picture.
TEST(Hotkeys, ATapBetweenTwoFramesActs)
{
    const std::vector<std::string> nprgl = {nprglCommand(), "--style", "toon+edges"};
    const std::string native =
        runHotkeys("tap_native", {nprglCommand(), "--style", "none"}, {"--frames", "4"}, "4");
    const std::string styled = runHotkeys("tap_styled", nprgl, {"--frames", "4"}, "2,4");
    const std::string keyed = runHotkeys(
        "tap_toggle", nprgl, {"--frames", "4", "--tap", "3", "Shift_R+F9"}, "2,4");
    EXPECT_GT(differing(shot(native, 4), shot(styled, 4)), 200) << "the style changes nothing";
    EXPECT_EQ(differing(shot(keyed, 2), shot(styled, 2)), 0);
    EXPECT_EQ(differing(shot(keyed, 4), shot(native, 4)), 0) << "the tap was missed";
    EXPECT_EQ(stderrOf(keyed).find("no key events"), std::string::npos) << stderrOf(keyed);
}

// The screenshot key writes the next frame styled and the same frame unstyled (drawn again
// from its calls), named <program>_<date>_<time>_<ms>_styled/_unstyled.png, then styles on.
// probe_hotkeys turns its cube a step every frame: a pair of two frames would differ.
TEST(Hotkeys, TheScreenshotKeyWritesAStyledAndAnUnstyledPicture)
{
    const std::vector<std::string> nprgl = {nprglCommand(), "--style", "toon+edges"};
    const std::string native =
        runHotkeys("shot_native", {nprglCommand(), "--style", "none"}, {"--frames", "5"},
                   "3,4,5");
    const std::string styled = runHotkeys("shot_styled", nprgl, {"--frames", "5"}, "3,4,5");
    const std::string home = freshDir("shot_config");
    const std::string pictures = home + "/pictures";
    writeFile(home + "/keys.conf", "screenshot_dir=" + pictures + "\n");
    const std::string keyed =
        runHotkeys("shot_keyed", nprgl, {"--frames", "5", "--press", "3", "Shift_R+F11"}, "5",
                   {{"NPRGL_CONFIG_FILE", home + "/keys.conf"}});
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(pictures)) {
        names.push_back(entry.path().filename().string());
    }
    ASSERT_EQ(names.size(), 2u);
    std::sort(names.begin(), names.end());
    const std::string stem = names[0].substr(0, names[0].size() - std::string("_styled.png").size());
    EXPECT_EQ(names[0], stem + "_styled.png");
    EXPECT_EQ(names[1], stem + "_unstyled.png");
    EXPECT_EQ(stem.rfind("probe_hotkeys_", 0), 0u) << stem;
    PngImage a, b;
    std::string error;
    ASSERT_TRUE(PngImage::read(pictures + "/" + names[0], a, error)) << error;
    ASSERT_TRUE(PngImage::read(pictures + "/" + names[1], b, error)) << error;
    EXPECT_GT(differing(shot(native, 3), shot(native, 4)), 20) << "the frames are alike";
    EXPECT_EQ(differing(a, shot(styled, 4)), 0) << "the styled picture is not frame 4";
    EXPECT_EQ(differing(b, shot(native, 4)), 0) << "the unstyled picture is not frame 4";
    EXPECT_EQ(stderrOf(keyed).find("cannot be drawn again"), std::string::npos)
        << stderrOf(keyed);
    EXPECT_EQ(differing(shot(keyed, 5), shot(styled, 5)), 0) << "styling not back on";
}

// The cycle key steps through the configured list: from toon+edges (not in the list) to its
// first entry, then the next.
TEST(Hotkeys, TheCycleKeyStepsThroughTheConfiguredStyles)
{
    const std::string home = freshDir("cycle_config");
    writeFile(home + "/keys.conf", "cycle=halftone, preset:pencil\n");
    const std::string keyed = runHotkeys(
        "cycle_keyed", {nprglCommand(), "--style", "toon+edges"},
        {"--frames", "6", "--press", "3", "Shift_R+F10", "--press", "5", "Shift_R+F10"}, "4,6",
        {{"NPRGL_CONFIG_FILE", home + "/keys.conf"}});
    const std::string halftone = runHotkeys("cycle_halftone",
                                            {nprglCommand(), "--style", "halftone"},
                                            {"--frames", "6"}, "4");
    const std::string pencil = runHotkeys("cycle_pencil", {nprglCommand(), "--preset", "pencil"},
                                          {"--frames", "6"}, "6");
    EXPECT_EQ(differing(shot(keyed, 4), shot(halftone, 4)), 0);
    EXPECT_EQ(differing(shot(keyed, 6), shot(pencil, 6)), 0);
}

// A held key acts once, however long it is held and whatever happens meanwhile: F9 (toggle)
// held from frame 3 to 10 turns styling off once, though F7 (reload) held from frame 5 to 8
// reads the configuration again (which binds the keys again), once.
TEST(Hotkeys, AHeldKeyActsOnceEvenAcrossAReload)
{
    const std::vector<std::string> nprgl = {nprglCommand(), "--style", "toon+edges"};
    const std::string native =
        runHotkeys("held_native", {nprglCommand(), "--style", "none"}, {"--frames", "10"}, "9");
    const std::string styled = runHotkeys("held_styled", nprgl, {"--frames", "10"}, "2,9");
    const std::string home = freshDir("held_config");
    writeFile(home + "/keys.conf", "toggle_key=F9\nreload_key=F7\n");
    const std::string keyed =
        runHotkeys("held_keyed", nprgl,
                   {"--frames", "10", "--hold", "3", "10", "F9", "--hold", "5", "8", "F7"}, "2,9",
                   {{"NPRGL_CONFIG_FILE", home + "/keys.conf"}});
    EXPECT_EQ(differing(shot(keyed, 2), shot(styled, 2)), 0);
    EXPECT_EQ(differing(shot(keyed, 9), shot(native, 9)), 0) << "styling not off";
    EXPECT_EQ(countOf(stderrOf(keyed), "reload key"), 1u) << stderrOf(keyed);
}

// A key name the keyboard does not have is reported at its file and line, as other bad lines.
TEST(Hotkeys, AnUnknownKeyIsNamedAtItsFileAndLine)
{
    const std::string home = freshDir("unknown_key_config");
    writeFile(home + "/keys.conf", "# keys\ncycle_key=NoSuchKey\n");
    const std::string run =
        runHotkeys("unknown_key", {nprglCommand(), "--style", "toon"}, {"--frames", "2"}, "2",
                   {{"NPRGL_CONFIG_FILE", home + "/keys.conf"}});
    EXPECT_NE(stderrOf(run).find(" " + home +
                                 "/keys.conf:2: cycle_key=NoSuchKey: no key "
                                 "'NoSuchKey' on this keyboard; cycle is unbound\n"),
              std::string::npos)
        << stderrOf(run);
}

// With the default cycle list, whose first entry is the configured look, the first press
// shows the next one (preset:cartoon), not the look already running.
TEST(Hotkeys, TheFirstCyclePressChangesTheLook)
{
    const std::string keyed = runHotkeys("cycle_first", {nprglCommand(), "--style", "toon"},
                                         {"--frames", "5", "--press", "3", "Shift_R+F10"}, "5");
    const std::string cartoon = runHotkeys("cycle_cartoon", {nprglCommand(), "--preset", "cartoon"},
                                           {"--frames", "5"}, "5");
    EXPECT_EQ(differing(shot(keyed, 5), shot(cartoon, 5)), 0) << stderrOf(keyed);
}

namespace {

// Pixels that differ inside the rectangle [x0, x1) x [y0, y1).
int differingIn(const PngImage& a, const PngImage& b, int x0, int y0, int x1, int y1)
{
    if (a.width != b.width || a.height != b.height) return -1;
    int n = 0;
    for (int y = y0; y < std::min(y1, int(a.height)); ++y) {
        for (int x = x0; x < std::min(x1, int(a.width)); ++x) {
            const size_t i = (size_t(y) * a.width + size_t(x)) * 4;
            int d = 0;
            for (int c = 0; c < 3; ++c) d += std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
            n += d > 6;
        }
    }
    return n;
}

struct ItemRect {
    int x = -1, y = -1, w = 0, h = 0;
};

// Where the overlay put an item ("overlay: item KEY at X Y W H", logged at debug level on the
// second frame it is open).
ItemRect itemAt(const std::string& log, const std::string& key)
{
    ItemRect r;
    const std::string tag = "overlay: item " + key + " at ";
    const size_t at = log.find(tag);
    if (at != std::string::npos) {
        std::sscanf(log.c_str() + at + tag.size(), "%d %d %d %d", &r.x, &r.y, &r.w, &r.h);
    }
    return r;
}

constexpr const char* kOverlaySize = "600";

} // namespace

// The overlay key (Shift_R+F8) held in frame 3 opens the overlay from that frame's end, held
// again in frame 6 closes it: its pixels are in frames 4 and 5 only, at the top left.
TEST(Overlay, ItsPixelsAppearOnlyWhileItIsOpen)
{
    const std::vector<std::string> nprgl = {nprglCommand(), "--style", "toon"};
    const std::string plain =
        runHotkeys("overlay_plain", nprgl, {"--size", kOverlaySize, "--frames", "7"}, "2,4,5,7");
    const std::string keyed = runHotkeys(
        "overlay_keyed", nprgl,
        {"--size", kOverlaySize, "--frames", "7", "--press", "3", "Shift_R+F8", "--press", "6",
         "Shift_R+F8"},
        "2,4,5,7");
    EXPECT_EQ(differing(shot(keyed, 2), shot(plain, 2)), 0);
    for (int f : {4, 5}) {
        // Its window's top left corner (title bar) is drawn; the far corner is the program's.
        EXPECT_GT(differingIn(shot(keyed, f), shot(plain, f), 8, 8, 200, 40), 4000) << f;
        EXPECT_EQ(differingIn(shot(keyed, f), shot(plain, f), 400, 400, 600, 600), 0) << f;
    }
    EXPECT_EQ(differing(shot(keyed, 7), shot(plain, 7)), 0) << "still drawn when closed";
    const std::string log = stderrOf(keyed);
    EXPECT_NE(log.find("nprgl: overlay open"), std::string::npos) << log;
    EXPECT_NE(log.find("nprgl: overlay closed"), std::string::npos) << log;
}

// Dragging toon.diffuse_threshold's slider (XTEST pointer and button) restyles the running
// program; "save" writes the look to the program's file, and the next start runs it.
TEST(Overlay, ASliderDragRestylesTheProgramAndSaveKeepsIt)
{
    // Where the items are: the layout is the same in every run of the same window size.
    const std::string layout = runHotkeys(
        "overlay_layout", {nprglCommand(), "--style", "toon", "--log-level", "debug"},
        {"--size", kOverlaySize, "--frames", "3"}, "3", {{"NPRGL_OVERLAY", "open"}});
    const ItemRect slider = itemAt(stderrOf(layout), "toon.diffuse_threshold");
    const ItemRect save = itemAt(stderrOf(layout), "save");
    ASSERT_GT(slider.w, 0) << stderrOf(layout);
    ASSERT_GT(save.w, 0) << stderrOf(layout);

    const std::string home = freshDir("overlay_drag_home");
    const int y = slider.y + slider.h / 2;
    const std::string dragged = runHotkeys(
        "overlay_drag", {nprglCommand(), "--style", "toon"},
        {"--size", kOverlaySize, "--frames", "12",
         "--pointer", "3", std::to_string(slider.x + 4), std::to_string(y),
         "--button", "4", "down",
         "--pointer", "5", std::to_string(slider.x + 140), std::to_string(y),
         "--button", "6", "up",
         "--pointer", "7", std::to_string(save.x + save.w / 2),
         std::to_string(save.y + save.h / 2),
         "--button", "8", "down", "--button", "9", "up",
         // Off the overlay, so that no tooltip covers the program's pixels compared below.
         "--pointer", "10", "590", "590"},
        "11", {{"NPRGL_OVERLAY", "open"}, {"XDG_CONFIG_HOME", home}});
    const std::string log = stderrOf(dragged);
    const size_t said = log.find("overlay: toon.diffuse_threshold=");
    ASSERT_NE(said, std::string::npos) << log;
    const double value = std::atof(log.c_str() + said + 32);
    EXPECT_GT(value, 0.4) << log;
    EXPECT_LT(value, 1.0) << log;

    std::ifstream file(home + "/nprgl/probe_hotkeys.conf");
    const std::string saved{std::istreambuf_iterator<char>(file), {}};
    EXPECT_NE(saved.find("style=toon\n"), std::string::npos) << saved;
    EXPECT_NE(saved.find("toon.diffuse_threshold="), std::string::npos) << saved;

    // Right of the overlay's window the cube is the program's, drawn with the new value: not
    // as a run without the drag, but as the next start that reads the saved file.
    const int right = 8 + 360 + 4;
    const std::string before = runHotkeys("overlay_before", {nprglCommand(), "--style", "toon"},
                                          {"--size", kOverlaySize, "--frames", "12"}, "11");
    const std::string next = runHotkeys("overlay_next", {nprglCommand()},
                                        {"--size", kOverlaySize, "--frames", "12"}, "11",
                                        {{"XDG_CONFIG_HOME", home}});
    EXPECT_GT(differingIn(shot(dragged, 11), shot(before, 11), right, 0, 600, 600), 100);
    EXPECT_EQ(differingIn(shot(dragged, 11), shot(next, 11), right, 0, 600, 600), 0);
    EXPECT_NE(stderrOf(next).find("probe_hotkeys: style toon, config toon.diffuse_threshold="),
              std::string::npos)
        << stderrOf(next);
}

// Dragged past the highlight threshold, the diffuse threshold's slider stops 0.02 below it
// (toon keeps t_d < t_h, and would move a value that is not): the value shown and saved is
// the one the style runs, which has no threshold of its own to put right.
TEST(Overlay, ASliderStopsWhereItsPairedValueKeepsIt)
{
    const std::string layout = runHotkeys(
        "paired_layout", {nprglCommand(), "--style", "toon", "--log-level", "debug"},
        {"--size", kOverlaySize, "--frames", "3"}, "3", {{"NPRGL_OVERLAY", "open"}});
    const ItemRect slider = itemAt(stderrOf(layout), "toon.diffuse_threshold");
    ASSERT_GT(slider.w, 0) << stderrOf(layout);
    const int y = slider.y + slider.h / 2;
    const std::string dragged = runHotkeys(
        "paired_drag", {nprglCommand(), "--style", "toon"},
        {"--size", kOverlaySize, "--frames", "9",
         "--pointer", "3", std::to_string(slider.x + 4), std::to_string(y),
         "--button", "4", "down",
         "--pointer", "5", std::to_string(slider.x + slider.w + 40), std::to_string(y),
         "--button", "6", "up", "--pointer", "7", "590", "590"},
        "9", {{"NPRGL_OVERLAY", "open"}});
    const std::string log = stderrOf(dragged);
    const size_t said = log.find("overlay: toon.diffuse_threshold=");
    ASSERT_NE(said, std::string::npos) << log;
    EXPECT_DOUBLE_EQ(std::atof(log.c_str() + said + 32), 0.9) << log; // the default t_h 0.92
    EXPECT_EQ(log.find("must be below highlight_threshold"), std::string::npos) << log;
}

// In a 300x300 window the overlay keeps to the left 60% of it (the rest is the program's
// picture) and runs no control past its right edge: its rows wrap, names go above their
// sliders, and it scrolls.
TEST(Overlay, ItFitsASmallWindow)
{
    const std::vector<std::string> nprgl = {nprglCommand(), "--style", "toon+paper+edges",
                                            "--log-level", "debug"};
    const std::vector<std::string> args = {"--size", "300", "--frames", "3"};
    const std::string plain = runHotkeys("small_plain", nprgl, args, "3");
    const std::string open =
        runHotkeys("small_open", nprgl, args, "3", {{"NPRGL_OVERLAY", "open"}});
    const std::string log = stderrOf(open);
    ItemRect window;
    const size_t at = log.find("overlay: window at ");
    ASSERT_NE(at, std::string::npos) << log;
    std::sscanf(log.c_str() + at + 19, "%d %d %d %d", &window.x, &window.y, &window.w, &window.h);
    EXPECT_LE(window.x + window.w, 186) << log;
    EXPECT_LE(window.y + window.h, 300) << log;
    EXPECT_GT(differingIn(shot(open, 3), shot(plain, 3), 0, 0, 100, 100), 2000) << "not drawn";
    EXPECT_EQ(differingIn(shot(open, 3), shot(plain, 3), 190, 0, 300, 300), 0);
    size_t items = 0;
    for (size_t i = log.find("overlay: item "); i != std::string::npos;
         i = log.find("overlay: item ", i + 1)) {
        const size_t end = log.find('\n', i);
        const std::string line = log.substr(i, end - i);
        const size_t coords = line.rfind(" at ");
        ItemRect r;
        std::sscanf(line.c_str() + coords + 4, "%d %d %d %d", &r.x, &r.y, &r.w, &r.h);
        EXPECT_GE(r.x, window.x) << line;
        EXPECT_LE(r.x + r.w, window.x + window.w) << line;
        ++items;
    }
    EXPECT_GT(items, 10u) << log;
}

// probe_hotkeys' poster, in window pixels of kOverlaySize (both axes).
constexpr int kPosterLo = 470, kPosterHi = 580;

// With the overlay open on probe_hotkeys' poster (`poster`: --textured or --decal): "pick", a
// click on the poster, `button` (a rule), "save". Returns the run; `home` is its config folder.
std::string pickPosterAndSave(const std::string& name, const std::string& poster,
                              const std::string& button, const std::string& home)
{
    const std::string layout = runHotkeys(
        name + "_layout", {nprglCommand(), "--style", "toon", "--log-level", "debug"},
        {"--size", kOverlaySize, "--frames", "3", poster}, "3", {{"NPRGL_OVERLAY", "open"}});
    const ItemRect pick = itemAt(stderrOf(layout), "pick");
    const ItemRect leave = itemAt(stderrOf(layout), button);
    const ItemRect save = itemAt(stderrOf(layout), "save");
    EXPECT_GT(pick.w * leave.w * save.w, 0) << stderrOf(layout);
    auto centre = [](const ItemRect& r) {
        return std::vector<std::string>{std::to_string(r.x + r.w / 2),
                                        std::to_string(r.y + r.h / 2)};
    };
    auto at = [](int frame, const std::vector<std::string>& xy) {
        return std::vector<std::string>{"--pointer", std::to_string(frame), xy[0], xy[1]};
    };
    std::vector<std::string> args = {"--size", kOverlaySize, "--frames", "16", poster};
    for (const auto& step : {at(3, centre(pick)), at(6, {"525", "525"}),
                             at(9, centre(leave)), at(12, centre(save)), at(15, {"590", "10"})}) {
        args.insert(args.end(), step.begin(), step.end());
    }
    for (int down : {4, 7, 10, 13}) {
        args.insert(args.end(), {"--button", std::to_string(down), "down", "--button",
                                 std::to_string(down + 1), "up"});
    }
    return runHotkeys(name + "_run", {nprglCommand(), "--style", "toon"}, args, "15",
                      {{"NPRGL_OVERLAY", "open"}, {"XDG_CONFIG_HOME", home}});
}

// The poster (lower right) of `ruled` and of a next start with the config folder `home` is
// drawn as the program draws it; the cube (right of the overlay, above the poster) is styled.
void expectPosterLeft(const std::string& name, const std::string& poster,
                      const std::string& ruled, const std::string& home)
{
    const std::vector<std::string> toon = {nprglCommand(), "--style", "toon"};
    const std::vector<std::string> plain = {"--size", kOverlaySize, "--frames", "16", poster};
    const std::string native =
        runHotkeys(name + "_native", {nprglCommand(), "--style", "none"}, plain, "15");
    const std::string styled = runHotkeys(name + "_styled", toon, plain, "15");
    const std::string next =
        runHotkeys(name + "_next", toon, plain, "15", {{"XDG_CONFIG_HOME", home}});
    const int p0 = kPosterLo, p1 = kPosterHi;
    EXPECT_GT(differingIn(shot(styled, 15), shot(native, 15), p0, p0, p1, p1), 500)
        << "the style does not change the poster: the test cannot tell";
    EXPECT_EQ(differingIn(shot(ruled, 15), shot(native, 15), p0, p0, p1, p1), 0);
    EXPECT_EQ(differingIn(shot(next, 15), shot(native, 15), p0, p0, p1, p1), 0);
    EXPECT_EQ(differingIn(shot(ruled, 15), shot(styled, 15), 372, 0, 600, 460), 0);
    EXPECT_EQ(differingIn(shot(next, 15), shot(styled, 15), 372, 0, 600, 460), 0);
}

std::string savedRules(const std::string& home)
{
    std::ifstream file(home + "/nprgl/probe_hotkeys.conf");
    return {std::istreambuf_iterator<char>(file), {}};
}

// Pick (a click on the program's textured poster with the overlay's pick on), "leave texture",
// "save": the poster is drawn as the program draws it from then on, the cube still styled,
// and the rule (leave_texture=HASH, by the texture's content) holds at the next start.
TEST(Overlay, APickedTextureIsLeftAsTheProgramDrawsItAndTheRuleIsKept)
{
    const std::string home = freshDir("rule_home");
    const std::string ruled = pickPosterAndSave("rule", "--textured", "leave texture", home);
    const std::string log = stderrOf(ruled);
    EXPECT_NE(log.find("overlay: picked object"), std::string::npos) << log;
    const size_t rule = log.find("overlay: rule: leave texture ");
    ASSERT_NE(rule, std::string::npos) << log;
    const std::string hash = log.substr(rule + 29, 16);
    EXPECT_NE(savedRules(home).find("leave_texture=" + hash + "\n"), std::string::npos)
        << savedRules(home) << log;
    expectPosterLeft("rule", "--textured", ruled, home);
    const int p0 = kPosterLo, p1 = kPosterHi;

    // And in a replay of a recording, given the program's file (nprgl replay --rules).
    const std::string dir = freshDir("rule_replay");
    ProcessResult recorded = runProcess(
        under({nprglCommand(), "record", "--style", "none", "-o", dir + "/poster.nprgl"},
              {hotkeyProbe(), "--size", kOverlaySize, "--frames", "4", "--textured"}),
        {{"XDG_CONFIG_HOME", freshDir("rule_replay_home")}, {"NPRGL_CONFIG_FILE", ""}});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err;
    auto replay = [&](const std::string& name, std::vector<std::string> extra) {
        std::vector<std::string> cmd = {nprglCommand(), "replay", dir + "/poster.nprgl", "-o",
                                        dir + "/" + name, "--frames", "3"};
        cmd.insert(cmd.end(), extra.begin(), extra.end());
        ProcessResult r = runProcess(cmd);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        PngImage image;
        std::string error;
        EXPECT_TRUE(PngImage::read(dir + "/" + name + "/frame_0000000003.png", image, error))
            << error;
        return image;
    };
    const PngImage none = replay("none", {"--style", "none"});
    const PngImage toonReplay = replay("toon", {"--style", "toon"});
    const PngImage ruledReplay =
        replay("ruled", {"--style", "toon", "--rules", home + "/nprgl/probe_hotkeys.conf"});
    EXPECT_GT(differingIn(toonReplay, none, p0, p0, p1, p1), 500);
    EXPECT_EQ(differingIn(ruledReplay, none, p0, p0, p1, p1), 0);
    EXPECT_EQ(differingIn(ruledReplay, toonReplay, 0, 0, 600, 460), 0);
}

// The same with the poster drawn as a decal (polygon offset) and "leave state": the pick says
// the poster is a decal, the rule leaves decals (leave_state=decal), now and at the next start.
TEST(Overlay, APickedDrawStateIsLeftAsTheProgramDrawsItAndTheRuleIsKept)
{
    const std::string home = freshDir("state_rule_home");
    const std::string ruled = pickPosterAndSave("state_rule", "--decal", "leave state", home);
    const std::string log = stderrOf(ruled);
    EXPECT_NE(log.find("overlay: picked object"), std::string::npos) << log;
    EXPECT_NE(log.find(" faces), decal, texture "), std::string::npos) << log;
    EXPECT_NE(log.find("overlay: rule: leave state decal\n"), std::string::npos) << log;
    EXPECT_NE(savedRules(home).find("leave_state=decal\n"), std::string::npos)
        << savedRules(home) << log;
    EXPECT_EQ(savedRules(home).find("leave_texture"), std::string::npos) << savedRules(home);
    expectPosterLeft("state_rule", "--decal", ruled, home);
}

// The keyboard reaches the overlay too (polled, as the pointer): Ctrl+click on a slider and
// typing "0.75", Enter, sets the value exactly.
TEST(Overlay, KeysTypeAValueIntoASlider)
{
    const std::string layout = runHotkeys(
        "keys_layout", {nprglCommand(), "--style", "toon", "--log-level", "debug"},
        {"--size", kOverlaySize, "--frames", "3"}, "3", {{"NPRGL_OVERLAY", "open"}});
    const ItemRect slider = itemAt(stderrOf(layout), "toon.diffuse_threshold");
    ASSERT_GT(slider.w, 0) << stderrOf(layout);
    const std::string typed = runHotkeys(
        "keys_typed", {nprglCommand(), "--style", "toon"},
        {"--size", kOverlaySize, "--frames", "12",
         "--pointer", "3", std::to_string(slider.x + 60), std::to_string(slider.y + slider.h / 2),
         "--press", "4", "Control_L", "--button", "4", "down", "--button", "5", "up",
         "--press", "6", "0", "--press", "7", "period", "--press", "8", "7",
         "--press", "9", "5", "--press", "10", "Return"},
        "12", {{"NPRGL_OVERLAY", "open"}});
    EXPECT_NE(stderrOf(typed).find("overlay: toon.diffuse_threshold=0.75\n"), std::string::npos)
        << stderrOf(typed);
}

// With toon+paper+edges running, the 'add style' list offers a shading style as a replacement
// of toon (a chain takes one): choosing halftone there and 'add style' runs halftone+paper+edges
// from the next frame, and 'save' writes that chain, which the next start reads without a
// skipped line.
TEST(Overlay, AShadingStyleFromTheAddListReplacesTheChainsOne)
{
    const std::vector<std::string> chain = {nprglCommand(), "--style", "toon+paper+edges"};
    // The list opened (a click on it at frames 4-5) for the places of its entries.
    const std::vector<std::string> open = {"--size", kOverlaySize, "--pointer", "3",
                                           "",       "",           "--button",  "4",
                                           "down",   "--button",   "5",         "up"};
    auto openAt = [&](const ItemRect& list, int frames) {
        std::vector<std::string> args = open;
        args[4] = std::to_string(list.x + list.w / 2);
        args[5] = std::to_string(list.y + list.h / 2);
        args.insert(args.end(), {"--frames", std::to_string(frames)});
        return args;
    };
    std::vector<std::string> debug = chain;
    debug.insert(debug.end(), {"--log-level", "debug"});
    const std::string closed =
        runHotkeys("add_closed", debug, {"--size", kOverlaySize, "--frames", "3"}, "3",
                   {{"NPRGL_OVERLAY", "open"}});
    const ItemRect list = itemAt(stderrOf(closed), "add");
    const ItemRect add = itemAt(stderrOf(closed), "add style");
    const ItemRect save = itemAt(stderrOf(closed), "save");
    ASSERT_GT(list.w * add.w * save.w, 0) << stderrOf(closed);
    const std::string opened =
        runHotkeys("add_opened", debug, openAt(list, 8), "8", {{"NPRGL_OVERLAY", "open"}});
    const ItemRect halftone = itemAt(stderrOf(opened), "add halftone");
    ASSERT_GT(halftone.w, 0) << stderrOf(opened);

    const std::string home = freshDir("add_home");
    std::vector<std::string> args = openAt(list, 18);
    auto clickAt = [&](int frame, const ItemRect& r) {
        args.insert(args.end(),
                    {"--pointer", std::to_string(frame), std::to_string(r.x + r.w / 2),
                     std::to_string(r.y + r.h / 2), "--button", std::to_string(frame + 1), "down",
                     "--button", std::to_string(frame + 2), "up"});
    };
    clickAt(7, halftone);
    clickAt(10, add);
    clickAt(13, save);
    args.insert(args.end(), {"--pointer", "16", "590", "590"});
    const std::string added = runHotkeys("add_run", chain, args, "17",
                                         {{"NPRGL_OVERLAY", "open"}, {"XDG_CONFIG_HOME", home}});
    const std::string saved = savedRules(home);
    EXPECT_NE(saved.find("style=halftone+paper+edges\n"), std::string::npos)
        << saved << stderrOf(added);

    // Right of the overlay the program runs halftone+paper+edges, as a start with it does.
    const std::vector<std::string> plain = {"--size", kOverlaySize, "--frames", "18"};
    const std::string toon = runHotkeys("add_toon", chain, plain, "17");
    const std::string expected = runHotkeys(
        "add_halftone", {nprglCommand(), "--style", "halftone+paper+edges"}, plain, "17");
    EXPECT_GT(differingIn(shot(toon, 17), shot(expected, 17), 372, 0, 600, 600), 100);
    EXPECT_EQ(differingIn(shot(added, 17), shot(expected, 17), 372, 0, 600, 600), 0);
    const std::string next =
        runHotkeys("add_next", {nprglCommand()}, plain, "17", {{"XDG_CONFIG_HOME", home}});
    EXPECT_EQ(stderrOf(next).find("skipped"), std::string::npos) << stderrOf(next);
    EXPECT_NE(stderrOf(next).find("probe_hotkeys: style halftone+paper+edges"), std::string::npos)
        << stderrOf(next);
}
