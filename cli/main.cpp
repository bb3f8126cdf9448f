// nprgl: run a legacy OpenGL program through the NPR interposer.
//
//   nprgl [run] [--style S] [--set key=value]... [--] PROGRAM ARGS...
//   nprgl record|replay|compare|dump|info|export|styles|help|version ...

#include "cli/CaptureCommands.h"
#include "cli/CompareCommand.h"
#include "cli/InfoCommand.h"
#include "cli/RunCommand.h"
#include "cli/StylesCommand.h"
#include "common/Log.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr const char* kFooter = R"(Usage: nprgl [run] [OPTIONS] [--] PROGRAM [ARGS...]
       nprgl COMMAND [OPTIONS] ...   (nprgl help COMMAND for its options)

Commands:
  run (default)   run PROGRAM with libnprgl.so preloaded
  record          run PROGRAM and record its GL stream, unstyled unless --style or --preset:
                  nprgl record [-o FILE] [--force] [--frames A-B] [--] PROGRAM ARGS...
                  (default FILE: <program>.nprgl; an existing capture is replaced only with
                  --force); says what was recorded when the program ends
  replay          render a capture headless into PNGs or a video: nprgl replay FILE
                  (-o DIR | --video out.mp4 [--fps N] | --stats) [--style S] [--set k=v]...
                  [--frames A-B] [--size WxH] [--context N]
  compare         replay a capture natively and in a style and measure how alike they are:
                  nprgl compare FILE [--style S|--preset P] [--frames A-B] [--json OUT] [-o DIR]
  dump            print a capture's calls: nprgl dump FILE [--frames A-B] [--grep NAME]
  info            print a capture's metadata, frames, calls and what was not captured:
                  nprgl info FILE [--json]
  export          write a frame's reconstructed meshes: nprgl export FILE --frame N -o out.obj
                  [--space eye|object] (also .ply, .off)
  styles          list the styles, their parameters, defaults and ranges
  help [COMMAND]  this text, or a command's options
  version         nprgl's version

A program named like a command runs with "run" or "--" first: nprgl run help.
NAME=value words before the program go to its environment, as in a shell; every word from
the program on is its own, untouched (so nprgl %command% works as a Steam launch option).
Exit status: the program's own (run, record); 2 for a usage error (an unknown option, a bad
value, a missing argument); 1 when a command fails (an unreadable or damaged file, nothing
to write); 126 or 127 when the program cannot be started.

Environment (set by the options above; plain LD_PRELOAD=libnprgl.so PROGRAM reads them too):
  NPRGL_STYLE       style chain, e.g. none
  NPRGL_CONFIG      style parameters, key=value,key=value
  NPRGL_PRESET      a preset name or file (applied under NPRGL_STYLE and NPRGL_CONFIG)
  NPRGL_CONFIG_FILE the one configuration file to read, instead of
                    $XDG_CONFIG_HOME/nprgl/nprgl.conf and <program>.conf beside it (the
                    options and variables above win over the files; a changed file applies
                    at the next frame)
  NPRGL_SCREENSHOT  frames=1,10,100;dir=out writes <program>_<frame>.png before each swap
  NPRGL_RECORD      record the GL stream to this file (NPRGL_RECORD_FRAMES=A-B)
  NPRGL_OVERLAY     open: the overlay from the first frame (default closed)
  NPRGL_EXPORT      frame=N;dir=D writes frame N's reconstructed meshes as D/<program>_N.obj
  NPRGL_LOG_LEVEL   error, warn, info (default) or debug
  NPRGL_LOG_FILE    log to this file instead of stderr
  NPRGL_REAL_LIBGL  the OpenGL library to forward to instead of libGL.so.1
  NPRGL_LIBRARY     the libnprgl.so this command preloads)";

// Index of the program name: after "--", or the first word that is not an option or an
// option's value. CLI11 only sees what comes before, so the program's own arguments are
// passed on untouched and in order.
int programIndex(int argc, char** argv, int first)
{
    for (int i = first; i < argc; ++i) {
        const char* arg = argv[i];
        if (std::strcmp(arg, "--") == 0) return i + 1;
        if (arg[0] != '-') return i;
        bool flag = std::strcmp(arg, "--help") == 0 || std::strcmp(arg, "-h") == 0 ||
                    std::strcmp(arg, "--version") == 0 || std::strcmp(arg, "--force") == 0;
        // -ofile style short options carry their value.
        if (arg[1] != '-' && arg[1] && arg[2]) flag = true;
        if (!flag && !std::strchr(arg, '=')) ++i; // skip the option's value
    }
    return argc;
}

constexpr int kUsageError = 2;

// CLI11's own exit codes (106 for a bad value, 109 for an extra argument...) become the one
// code nprgl gives every usage error; --help and --version print and succeed.
bool parsed(CLI::App& app, int argc, char** argv, int& exitCode)
{
    try {
        app.parse(argc, argv);
        return true;
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) {
            exitCode = app.exit(e);
            return false;
        }
        std::fprintf(stderr, "%s: %s (see %s --help)\n", app.get_name().c_str(), e.what(),
                     app.get_name().c_str());
        exitCode = kUsageError;
        return false;
    }
}

} // namespace

int replayMain(int argc, char** argv)
{
    nprgl::cli::ReplayCommandOptions o;
    CLI::App app{"Render a capture headless (OSMesa) into PNGs frame_0000000042.png or a video",
                 "nprgl replay"};
    app.add_option("file", o.file, "the capture")->required();
    app.add_option("-o,--output", o.outDir, "directory for the PNGs (none: render only)");
    app.add_flag("--stats", o.stats,
                 "print each frame's 3D polygon draws, styled and left by reason (the run's "
                 "totals are logged at the end), the textures drawn as drawings so far, and the "
                 "colour it cleared the window to");
    app.add_flag("--overlays", o.overlays,
                 "with --stats: also each 2D draw's pixels and contrast with its surroundings "
                 "(WCAG ratio), read around the draw (slow: for nprgl compare)");
    app.add_option("-s,--style", o.style, "style chain");
    app.add_option("--preset", o.preset, "a shipped preset (see nprgl styles) or a preset file");
    app.add_option("--set", o.settings, "style parameter, style.param=value (repeatable)")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option("--frames", o.frames, "frames to write, e.g. 1-10");
    app.add_option("--size", o.size,
                   "render size WxH (default: the recorded size; the program's viewport and "
                   "scissor are scaled to it, so the frame is its picture resized)");
    app.add_option("--context", o.context, "which context's stream (default: the longest)");
    app.add_option("--video", o.video,
                   "also encode the frames into this video: .mp4, .mkv or .mov (H.264), .webm "
                   "(VP9)");
    app.add_option("--fps", o.fps, "the video's frame rate (default 30)");
    app.add_option("--rules", o.rules,
                   "a configuration file (the program's, ~/.config/nprgl/PROGRAM.conf) whose "
                   "leave_texture and leave_state rules apply");
    if (int code; !parsed(app, argc, argv, code)) return code;
    return nprgl::cli::replayCommand(o);
}

int compareMain(int argc, char** argv)
{
    nprgl::cli::CompareOptions o;
    CLI::App app{"Replay a capture natively (style none) and in a style, and measure per frame "
                 "the share of drawn pixels within CIELAB dE 10 of native (fidelity), the "
                 "pixels drawn natively that no styled object covers and that changed "
                 "(missing), and per object its colour against native (palette)",
                 "nprgl compare"};
    app.add_option("file", o.file, "the capture")->required();
    app.add_option("-s,--style", o.style, "style chain (default: the default style)");
    app.add_option("--preset", o.preset, "a shipped preset or a preset file");
    app.add_option("--set", o.settings, "style parameter, style.param=value (repeatable)")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option("--frames", o.frames, "frames to compare, e.g. 1-10 (default: all)");
    app.add_option("--json", o.json, "write the figures per frame and per object to this file");
    app.add_option("-o,--output", o.outDir,
                   "directory for a diff picture per frame: native | style | difference");
    app.add_option("--context", o.context, "which context's stream (default: the longest)");
    if (int code; !parsed(app, argc, argv, code)) return code;
    return nprgl::cli::compareCommand(o);
}

int dumpMain(int argc, char** argv)
{
    std::string file, frames, grep;
    CLI::App app{"Print a capture's calls, one per line", "nprgl dump"};
    app.add_option("file", file, "the capture")->required();
    app.add_option("--frames", frames, "frames to print, e.g. 1-10");
    app.add_option("--grep", grep, "only calls whose name contains NAME");
    if (int code; !parsed(app, argc, argv, code)) return code;
    return nprgl::cli::dumpCommand(file, frames, grep);
}

int infoMain(int argc, char** argv)
{
    std::string file;
    bool json = false;
    CLI::App app{"Print a capture's metadata, frames and calls", "nprgl info"};
    app.add_option("file", file, "the capture")->required();
    app.add_flag("--json", json, "one JSON object instead of text");
    if (int code; !parsed(app, argc, argv, code)) return code;
    return nprgl::cli::infoCommand(file, json);
}

int exportMain(int argc, char** argv)
{
    std::string file, output, space = "eye";
    uint64_t frame = 1;
    unsigned context = 0;
    CLI::App app{"Write a frame's reconstructed meshes (OBJ with one group per object, PLY, OFF)",
                 "nprgl export"};
    app.add_option("file", file, "the capture")->required();
    app.add_option("--frame", frame, "the frame (counted from 1)")->required();
    app.add_option("-o,--output", output, "out.obj, out.ply or out.off")->required();
    app.add_option("--space", space, "eye (as the camera saw it, default) or object");
    app.add_option("--context", context, "which context's stream (default: the first)");
    if (int code; !parsed(app, argc, argv, code)) return code;
    return nprgl::cli::exportCommand(file, frame, output, space, context);
}

int dispatch(int argc, char** argv)
{
    const char* command = argc > 1 ? argv[1] : "";
    if (std::strcmp(command, "styles") == 0) {
        CLI::App app{"List nprgl's styles", "nprgl styles"};
        if (int code; !parsed(app, argc - 1, argv + 1, code)) return code;
        return nprgl::cli::listStyles();
    }
    if (std::strcmp(command, "version") == 0 && argc == 2) {
        std::printf("nprgl %s\n", NPRGL_VERSION);
        return 0;
    }
    if (std::strcmp(command, "help") == 0) {
        // nprgl help COMMAND is COMMAND --help; nprgl help is nprgl --help.
        if (argc > 3) {
            std::fprintf(stderr, "nprgl help: one command at most (see nprgl --help)\n");
            return kUsageError;
        }
        std::string name = argc == 3 ? argv[2] : "run";
        if (name == "help" || name == "version") name = "run";
        char helpFlag[] = "--help";
        char* args[] = {argv[0], name.data(), helpFlag, nullptr};
        for (const char* known :
             {"run", "record", "replay", "compare", "dump", "info", "export", "styles"}) {
            if (name == known) return dispatch(3, args);
        }
        std::fprintf(stderr, "nprgl help: no command '%s' (see nprgl --help)\n", name.c_str());
        return kUsageError;
    }
    // The commands that run the pipeline in this process log as the library does
    // (NPRGL_LOG_LEVEL, NPRGL_LOG_FILE); run and record leave both to the program's library.
    for (const char* inProcess : {"replay", "dump", "compare", "info", "export"}) {
        if (std::strcmp(command, inProcess) == 0) nprgl::initLog();
    }
    if (std::strcmp(command, "replay") == 0) return replayMain(argc - 1, argv + 1);
    if (std::strcmp(command, "dump") == 0) return dumpMain(argc - 1, argv + 1);
    if (std::strcmp(command, "compare") == 0) return compareMain(argc - 1, argv + 1);
    if (std::strcmp(command, "info") == 0) return infoMain(argc - 1, argv + 1);
    if (std::strcmp(command, "export") == 0) return exportMain(argc - 1, argv + 1);
    // "run" is the default command and may be left out; "record" is run plus a capture.
    const bool record = std::strcmp(command, "record") == 0;
    int skip = record || std::strcmp(command, "run") == 0 ? 1 : 0;

    nprgl::cli::RunOptions options;
    CLI::App app{"nprgl renders unmodified legacy OpenGL programs in non-photorealistic styles.",
                 "nprgl"};
    app.footer(kFooter);
    app.set_version_flag("--version", std::string("nprgl ") + NPRGL_VERSION);
    app.add_option("-s,--style", options.style, "style chain (default: the best-looking one)");
    app.add_option("--preset", options.preset,
                   "a shipped preset (see nprgl styles) or a file of key=value lines");
    app.add_option("--set", options.settings, "style parameter, style.param=value (repeatable)")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option("--screenshot", options.screenshot,
                   "write frames as PNG: frames=1,10,100;dir=out");
    app.add_option("--log-level", options.logLevel, "error, warn, info or debug");
    app.add_option("--log-file", options.logFile, "log to this file instead of stderr");
    CLI::Option* video = app.add_option(
        "--video", options.video,
        "encode the program's frames into this file (.mp4, .mkv, .mov: H.264; .webm: VP9) as "
        "it runs; the video key (Shift_R+F6) stops it and starts the next file");
    app.add_option("--fps", options.fps, "the video's frame rate (default 30)")->needs(video);
    app.add_flag("--video-on-key", options.videoOnKey,
                 "the first recording starts at the video key, not at the first frame")
        ->needs(video);
    options.record = record;
    if (record) {
        app.add_option("-o,--output", options.recordFile, "the capture file");
        app.add_option("--frames", options.recordFrames, "frames to record, e.g. 1-100");
        app.add_flag("--force", options.recordForce,
                     "replace FILE if it is an nprgl capture (any other file is never replaced)");
    }
    int program = programIndex(argc, argv, 1 + skip);
    // The options end where the program begins; a "--" in between is not an option.
    int optionsEnd =
        program > 1 + skip && std::strcmp(argv[program - 1], "--") == 0 ? program - 1 : program;
    std::vector<char*> ours(argv + skip, argv + optionsEnd);
    ours[0] = argv[0];
    if (int code; !parsed(app, int(ours.size()), ours.data(), code)) return code;
    options.command.assign(argv + program, argv + argc);
    return nprgl::cli::runProgram(options);
}

int main(int argc, char** argv) { return dispatch(argc, argv); }
