#include "cli/CompareCommand.h"

#include "capture/CaptureReader.h"
#include "common/FrameFidelity.h"
#include "common/OverlayLegibility.h"
#include "common/PngImage.h"
#include "styles/Presets.h"
#include "styles/Style.h"
#include "styles/StyleRegistry.h"
#include "styles/StyleSettings.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fcntl.h>
#include <map>
#include <optional>
#include <sys/wait.h>
#include <unistd.h>

namespace nprgl::cli {

namespace {

namespace fs = std::filesystem;

int fail(const std::string& message, int code = 1)
{
    std::fprintf(stderr, "nprgl: %s\n", message.c_str());
    return code;
}

// Runs this executable with `args`; its stdout into `out` when given. False with a message
// when it cannot run or exits other than 0 (its stderr went to ours).
bool runSelf(const std::vector<std::string>& args, std::string* out, std::string& error)
{
    int pipeFds[2] = {-1, -1};
    if (out && pipe(pipeFds) != 0) {
        error = "cannot make a pipe";
        return false;
    }
    const pid_t pid = fork();
    if (pid < 0) {
        error = "cannot start a replay";
        return false;
    }
    if (pid == 0) {
        if (out) {
            dup2(pipeFds[1], STDOUT_FILENO);
            close(pipeFds[0]);
            close(pipeFds[1]);
        } else {
            // The replays' own figures are not compare's.
            const int null = open("/dev/null", O_WRONLY);
            if (null >= 0) dup2(null, STDOUT_FILENO);
        }
        // Their warnings are compare's too; their progress and counts are not.
        setenv("NPRGL_LOG_LEVEL", "warn", 1);
        std::vector<char*> argv;
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv("/proc/self/exe", argv.data());
        _exit(127);
    }
    if (out) {
        close(pipeFds[1]);
        char buffer[4096];
        ssize_t n;
        while ((n = read(pipeFds[0], buffer, sizeof buffer)) > 0) out->append(buffer, size_t(n));
        close(pipeFds[0]);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) break;
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
    error = WIFSIGNALED(status) ? "the replay ended by signal " + std::to_string(WTERMSIG(status))
                                : "the replay failed (status " +
                                      std::to_string(WEXITSTATUS(status)) + ")";
    return false;
}

// frame_0000000042.png -> 42, for every such file in `dir`.
std::map<uint64_t, fs::path> framesIn(const fs::path& dir)
{
    std::map<uint64_t, fs::path> frames;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        unsigned long long n = 0;
        if (std::sscanf(name.c_str(), "frame_%llu.png", &n) == 1) frames[n] = entry.path();
    }
    return frames;
}

// Calls take(line) for each line of text.
template <typename Take> void forEachLine(const std::string& text, Take take)
{
    size_t pos = 0;
    while (pos < text.size()) {
        size_t eol = text.find('\n', pos);
        if (eol == std::string::npos) eol = text.size();
        take(text.substr(pos, eol - pos));
        pos = eol + 1;
    }
}

// The replay's --stats lines, by frame: "frame 3: 3D polygon draws: 12 styled, ...".
std::map<uint64_t, std::string> statsByFrame(const std::string& text)
{
    std::map<uint64_t, std::string> out;
    forEachLine(text, [&](const std::string& line) {
        unsigned long long frame = 0;
        int used = 0;
        if (std::sscanf(line.c_str(), "frame %llu: 3D polygon draws: %n", &frame, &used) == 1 &&
            used > 0) {
            out[frame] = line.substr(size_t(used));
        }
    });
    return out;
}

// The replays' --overlays lines "frame 3: 2D draws: 2 measured: 120:12.41 0:-", by frame; a
// line that does not parse is said and its frame left unjudged.
std::map<uint64_t, std::vector<OverlayDraw>> overlaysByFrame(const std::string& text,
                                                             const char* which)
{
    std::map<uint64_t, std::vector<OverlayDraw>> out;
    forEachLine(text, [&](const std::string& line) {
        unsigned long long frame = 0;
        int used = 0;
        if (std::sscanf(line.c_str(), "frame %llu: 2D draws: %n", &frame, &used) != 1 ||
            used <= 0) {
            return;
        }
        std::vector<OverlayDraw> draws;
        if (OverlayLegibility::parse(line.substr(size_t(used)), draws)) {
            out[frame] = std::move(draws);
        } else {
            std::fprintf(stderr, "nprgl: frame %llu: the %s replay's 2D draws do not read: %s\n",
                         frame, which, line.c_str());
        }
    });
    return out;
}

// The native replay's --stats lines "frame 3: background: cleared to 0 0 0", by frame: the
// colour each frame's last clear of the whole window left.
std::map<uint64_t, std::array<uint8_t, 3>> clearsByFrame(const std::string& text)
{
    std::map<uint64_t, std::array<uint8_t, 3>> out;
    forEachLine(text, [&](const std::string& line) {
        unsigned long long frame = 0;
        unsigned r = 0, g = 0, b = 0;
        if (std::sscanf(line.c_str(), "frame %llu: background: cleared to %u %u %u", &frame, &r,
                        &g, &b) == 4 &&
            r < 256 && g < 256 && b < 256) {
            out[frame] = {uint8_t(r), uint8_t(g), uint8_t(b)};
        }
    });
    return out;
}

std::string jsonString(const std::string& s)
{
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if (uint8_t(c) < 0x20) {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\u%04x", c);
            out += esc;
        } else out += c;
    }
    return out + "\"";
}

std::string jsonTone(const FrameFidelity::Tone& t)
{
    char text[128];
    std::snprintf(text, sizeof text, "{\"lightness\": %.2f, \"chroma\": %.2f, \"hue\": %.1f}",
                  t.lightness, t.chroma, t.hue);
    return text;
}

void writeFrameJson(std::FILE* f, uint64_t frame, const FrameFidelity& m,
                    const std::string& stats, const OverlayLegibility* overlays, bool last)
{
    std::fprintf(f,
                 "    {\"frame\": %llu, \"drawn\": %llu, \"fidelity\": %.5f, \"missing\": %.5f, "
                 "\"clear\": [%d, %d, %d], \"clearFrom\": \"%s\", \"draws\": %s,\n",
                 static_cast<unsigned long long>(frame),
                 static_cast<unsigned long long>(m.drawn), m.fidelity(), m.missingShare(),
                 m.clear[0], m.clear[1], m.clear[2], m.clearFromStream ? "stream" : "border",
                 jsonString(stats).c_str());
    if (!overlays || !overlays->mismatch.empty()) {
        std::fprintf(f, "     \"overlays\": null,\n");
    } else {
        std::fprintf(f, "     \"overlays\": {\"judged\": %zu, \"short\": [", overlays->judged);
        for (size_t i = 0; i < overlays->shortOf.size(); ++i) {
            const OverlayLegibility::Short& o = overlays->shortOf[i];
            std::fprintf(f, "%s{\"draw\": %zu, \"pixels\": %u, \"native\": %.2f, \"styled\": %.2f}",
                         i ? ", " : "", o.index, o.pixels, o.native, o.styled);
        }
        std::fprintf(f, "]},\n");
    }
    std::fprintf(f, "     \"objects\": [");
    for (size_t i = 0; i < m.objects.size(); ++i) {
        const FrameFidelity::Object& o = m.objects[i];
        std::fprintf(f,
                     "%s\n      {\"id\": %u, \"pixels\": %u, \"meanDeltaE\": %.2f, \"native\": "
                     "%s, \"style\": %s, \"bbox\": [%d, %d, %d, %d], \"styled\": true, "
                     "\"judged\": %s, \"hueKept\": %s, \"orderKept\": %s, \"paletteOk\": %s}",
                     i ? "," : "", o.id, o.pixels, o.meanDeltaE, jsonTone(o.native).c_str(),
                     jsonTone(o.styled).c_str(), o.box[0], o.box[1], o.box[2], o.box[3],
                     o.judged ? "true" : "false", o.hueKept ? "true" : "false",
                     o.orderKept ? "true" : "false", o.paletteOk() ? "true" : "false");
    }
    std::fprintf(f, "]}%s\n", last ? "" : ",");
}

// The chain compare's style runs, without its outline styles: where it has a shading or
// background style and an outline style. Empty otherwise (or when the chain does not parse:
// the styled replay says why).
std::string shadingChain(const CompareOptions& options)
{
    std::string chain = options.style, config, error;
    for (const std::string& s : options.settings) config += (config.empty() ? "" : ",") + s;
    StyleSettings settings;
    if (!Presets::combine(options.preset, chain, config, error) ||
        !StyleSettings::parse(chain, config, settings, error)) {
        return {};
    }
    std::string kept;
    bool outlines = false, shades = false;
    for (const StyleInfo* info : settings.chain()) {
        if (info->role == styles::StyleRole::Outline) {
            outlines = true;
            continue;
        }
        shades = shades || info->role == styles::StyleRole::Shading;
        kept += (kept.empty() ? "" : "+") + info->name;
    }
    return outlines && shades ? kept : std::string();
}

} // namespace

int compareCommand(const CompareOptions& options)
{
    {
        // A bad style, preset or value is a usage error, said before any replay runs.
        std::string config, error;
        for (const std::string& v : options.settings) config += (config.empty() ? "" : ",") + v;
        std::string chain = options.style;
        StyleSettings style;
        if (!Presets::combine(options.preset, chain, config, error)) {
            return fail("--preset: " + error, 2);
        }
        if (!StyleSettings::parse(chain, config, style, error)) return fail(error, 2);
    }
    {
        // Refused here, once, rather than by each replay below (a FIFO, a device, no file).
        capture::CaptureReader reader;
        std::string error;
        if (!reader.open(options.file, error)) return fail(error);
    }
    std::error_code ec;
    // A private scratch folder for the replays' frames, removed at the end.
    const fs::path tmp = fs::temp_directory_path(ec);
    if (ec || !fs::is_directory(tmp)) return fail("no usable temporary directory");
    std::string pattern = (tmp / "nprgl-compare-XXXXXX").string();
    if (!mkdtemp(pattern.data())) return fail("cannot make a folder in " + tmp.string());
    const fs::path scratch = pattern;
    struct Cleanup {
        fs::path dir;
        ~Cleanup()
        {
            std::error_code ignored;
            fs::remove_all(dir, ignored);
        }
    } cleanup{scratch};

    auto replayArgs = [&](const std::string& dir) {
        std::vector<std::string> a = {"nprgl", "replay", options.file, "-o", dir};
        if (!options.frames.empty()) a.insert(a.end(), {"--frames", options.frames});
        if (options.context) a.insert(a.end(), {"--context", std::to_string(options.context)});
        return a;
    };
    std::string error;
    const std::string nativeDir = (scratch / "native").string();
    std::vector<std::string> native = replayArgs(nativeDir);
    native.insert(native.end(), {"--style", "none", "--stats", "--overlays"});
    std::string nativeStats;
    if (!runSelf(native, &nativeStats, error)) return fail(options.file + ": " + error);
    const auto clears = clearsByFrame(nativeStats);
    const auto nativeOverlays = overlaysByFrame(nativeStats, "native");

    const std::string styleDir = (scratch / "style").string();
    std::vector<std::string> styled = replayArgs(styleDir);
    styled.insert(styled.end(), {"--stats", "--overlays"});
    if (!options.style.empty()) styled.insert(styled.end(), {"--style", options.style});
    if (!options.preset.empty()) styled.insert(styled.end(), {"--preset", options.preset});
    for (const std::string& s : options.settings) styled.insert(styled.end(), {"--set", s});
    std::string statsText;
    if (!runSelf(styled, &statsText, error)) return fail(options.file + ": " + error);
    const std::map<uint64_t, std::string> stats = statsByFrame(statsText);
    const auto styledOverlays = overlaysByFrame(statsText, "styled");

    // The palette is the shading's: the same chain without its outline styles, when it has
    // both (the ink over a thin part is most of its pixels, and no object's colour).
    const std::string shading = shadingChain(options);
    const std::string shadingDir = (scratch / "shading").string();
    if (!shading.empty()) {
        std::vector<std::string> a = replayArgs(shadingDir);
        a.insert(a.end(), {"--style", shading});
        if (!options.preset.empty()) a.insert(a.end(), {"--preset", options.preset});
        for (const std::string& s : options.settings) a.insert(a.end(), {"--set", s});
        if (!runSelf(a, nullptr, error)) return fail(options.file + ": " + error);
    }

    const std::string idsDir = (scratch / "ids").string();
    std::vector<std::string> ids = replayArgs(idsDir);
    ids.insert(ids.end(), {"--style", "ids"});
    if (!runSelf(ids, nullptr, error)) return fail(options.file + ": " + error);

    if (!options.outDir.empty()) {
        fs::create_directories(options.outDir, ec);
        if (ec) return fail("cannot create " + options.outDir + ": " + ec.message());
    }
    std::FILE* json = nullptr;
    if (!options.json.empty()) {
        json = std::fopen(options.json.c_str(), "w");
        if (!json) return fail("cannot write " + options.json);
        const std::string chain = !options.style.empty()    ? options.style
                                  : !options.preset.empty() ? "preset " + options.preset
                                                            : "default";
        std::fprintf(json, "{\"file\": %s, \"style\": %s, \"paletteOf\": %s, \"frames\": [\n",
                     jsonString(options.file).c_str(), jsonString(chain).c_str(),
                     jsonString(shading.empty() ? "the style" : shading).c_str());
    }

    const auto nativeFrames = framesIn(nativeDir);
    const auto styleFrames = framesIn(styleDir);
    const auto idsFrames = framesIn(idsDir);
    const auto shadingFrames = shading.empty() ? decltype(idsFrames)() : framesIn(shadingDir);
    std::vector<double> fidelities;
    uint64_t nativeDrawn = 0, missing = 0, judged = 0, failures = 0;
    uint64_t overlayDraws = 0, overlaysShort = 0, overlaysUnjudged = 0;
    size_t index = 0;
    for (const auto& [frame, nativePath] : nativeFrames) {
        ++index;
        const auto s = styleFrames.find(frame);
        if (s == styleFrames.end()) {
            std::fprintf(stderr, "nprgl: frame %llu: not replayed in the style\n",
                         static_cast<unsigned long long>(frame));
            continue;
        }
        PngImage a, b, c, e;
        if (!PngImage::read(nativePath.string(), a, error) ||
            !PngImage::read(s->second.string(), b, error)) {
            return fail(error);
        }
        const auto d = idsFrames.find(frame);
        if (d != idsFrames.end() && !PngImage::read(d->second.string(), c, error)) c = PngImage();
        const auto sh = shadingFrames.find(frame);
        if (sh != shadingFrames.end() && !PngImage::read(sh->second.string(), e, error)) {
            e = PngImage();
        }
        FrameFidelity m;
        const auto cl = clears.find(frame);
        const uint8_t* clear = cl == clears.end() ? nullptr : cl->second.data();
        if (!FrameFidelity::measure(a, b, c, !options.outDir.empty(), m, error, e, clear)) {
            return fail("frame " + std::to_string(frame) + ": " + error);
        }
        if (!options.outDir.empty()) {
            char name[64];
            std::snprintf(name, sizeof name, "/diff_%010llu.png",
                          static_cast<unsigned long long>(frame));
            if (!m.diff.write(options.outDir + name, error)) return fail(error);
        }
        const auto st = stats.find(frame);
        const std::string draws = st == stats.end() ? "" : st->second;
        // The 2D draws, when both replays measured this frame's.
        const auto no = nativeOverlays.find(frame), so = styledOverlays.find(frame);
        std::optional<OverlayLegibility> overlays;
        if (no != nativeOverlays.end() && so != styledOverlays.end()) {
            overlays = OverlayLegibility::judge(no->second, so->second);
            if (overlays->mismatch.empty()) {
                overlayDraws += overlays->judged;
                overlaysShort += overlays->shortOf.size();
            } else {
                ++overlaysUnjudged;
            }
        } else {
            ++overlaysUnjudged;
        }
        std::printf("frame %llu: fidelity %.3f, missing %.2f%%, %llu drawn px, %zu objects "
                    "(palette: %u of %u judged off); 2D draws: %s%s%s\n",
                    static_cast<unsigned long long>(frame), m.fidelity(),
                    100.0 * m.missingShare(), static_cast<unsigned long long>(m.drawn),
                    m.objects.size(), m.paletteFailures(), m.paletteJudged(),
                    overlays ? overlays->summary().c_str() : "not measured",
                    draws.empty() ? "" : "; 3D polygon draws: ", draws.c_str());
        fidelities.push_back(m.fidelity());
        nativeDrawn += m.nativeDrawn;
        missing += m.missing;
        judged += m.paletteJudged();
        failures += m.paletteFailures();
        if (json) {
            writeFrameJson(json, frame, m, draws, overlays ? &*overlays : nullptr,
                           index == nativeFrames.size());
        }
    }
    if (fidelities.empty()) {
        if (json) std::fclose(json);
        return fail(options.file + ": no frame to compare" +
                    (options.frames.empty() ? "" : " in --frames " + options.frames));
    }
    std::vector<double> sorted = fidelities;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.size() % 2 ? sorted[sorted.size() / 2]
                                            : 0.5 * (sorted[sorted.size() / 2 - 1] +
                                                     sorted[sorted.size() / 2]);
    const double missingShare = nativeDrawn ? double(missing) / double(nativeDrawn) : 0.0;
    std::printf("fidelity: median %.3f, min %.3f over %zu frames; missing %.2f%%; palette: "
                "%llu of %llu judged objects off; 2D draws: %llu of %llu short of their "
                "contrast%s\n",
                median, sorted.front(), sorted.size(), 100.0 * missingShare,
                static_cast<unsigned long long>(failures),
                static_cast<unsigned long long>(judged),
                static_cast<unsigned long long>(overlaysShort),
                static_cast<unsigned long long>(overlayDraws),
                overlaysUnjudged ? (" (" + std::to_string(overlaysUnjudged) +
                                    " frames not judged)").c_str()
                                 : "");
    if (json) {
        std::fprintf(json,
                     "  ],\n  \"summary\": {\"frames\": %zu, \"fidelityMedian\": %.5f, "
                     "\"fidelityMin\": %.5f, \"missing\": %.5f, \"paletteObjects\": %llu, "
                     "\"paletteFailures\": %llu, \"paletteOk\": %s, \"overlayDraws\": %llu, "
                     "\"overlaysShort\": %llu, \"overlayFramesUnjudged\": %llu}\n}\n",
                     sorted.size(), median, sorted.front(), missingShare,
                     static_cast<unsigned long long>(judged),
                     static_cast<unsigned long long>(failures), failures == 0 ? "true" : "false",
                     static_cast<unsigned long long>(overlayDraws),
                     static_cast<unsigned long long>(overlaysShort),
                     static_cast<unsigned long long>(overlaysUnjudged));
        if (std::fclose(json) != 0) return fail("cannot write " + options.json);
    }
    return 0;
}

} // namespace nprgl::cli
