// The abstracted versions of the program's textures: made off the frame, bound in their place.
#pragma once

#include "styles/GlFunctions.h"
#include "styles/textures/TextureImage.h"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace nprgl::styles {

// A shading style that draws the program's textures as drawings (toon.texture_detail < 1)
// asks for the texture to bind in place of one of the program's. The first time a texture's
// content is asked for, its level 0 is read back (RGBA8) and handed to a worker thread that
// makes TextureAbstraction::abstracted; until the result is there, the program's own texture
// is drawn, and the frame never waits for the work. Results are cached by content and
// detail, so two names with one image share one abstraction, and a texture uploaded again
// with the same content costs nothing. In a replay (setWait) the work is done at once in the
// calling thread, so a replayed frame's picture does not depend on timing.
//
// Left as the program's (each counted, and said once): a texture whose content is not known
// (rendered into, copied from the framebuffer: content 0), one whose content changed
// kChangesAllowed times, each within kChangingFrames of the one before (video, animated or
// procedural textures: a new abstraction every frame would cost a readback each frame and
// flicker; it is abstracted again once its content has held for kChangingFrames, so a name
// a program reuses for a new level's texture is not left for good), and one larger than
// kMaxTexels.
class AbstractTextures {
public:
    static constexpr int kChangesAllowed = 2;
    static constexpr uint64_t kChangingFrames = 60;
    static constexpr long kMaxTexels = 2048L * 2048L;

    struct Counts {
        int abstracted = 0;
        int unknownContent = 0;
        int changing = 0;
        int tooLarge = 0;
        bool any() const { return abstracted + unknownContent + changing + tooLarge > 0; }
        // "3 abstracted; left as the program's: 1 of unknown content, 0 changing, 0 too large"
        std::string describe() const;
    };

    AbstractTextures();
    ~AbstractTextures();
    AbstractTextures(const AbstractTextures&) = delete;
    AbstractTextures& operator=(const AbstractTextures&) = delete;

    // The name to bind in place of the program's `texture`, which is bound on the active
    // unit's GL_TEXTURE_2D when this is called; 0: keep the program's. `content` is its
    // content hash (0: not known). The substitute samples as the program's does (its filters
    // and wrap modes, copied at each bind).
    GLuint substitute(const GlFunctions& gl, GLuint texture, uint64_t content, float detail,
                      uint64_t frame);
    // The GL textures go (the context is current); the worker's unfinished jobs are dropped.
    void destroy(const GlFunctions& gl);
    const Counts& counts() const { return mCounts; }

    static void setWait(bool wait);

private:
    struct Job {
        uint64_t key;
        TextureImage image;
        float detail;
    };
    // Shared with the worker thread, which outlives this object if it is still working.
    struct Shared {
        std::mutex mutex;
        std::condition_variable wake;
        std::deque<Job> jobs;
        std::unordered_map<uint64_t, TextureImage> done;
        bool stop = false;
    };
    struct Entry {
        enum class State { Pending, Ready, Failed } state = State::Pending;
        GLuint texture = 0;
        GLint filters[4] = {0, 0, 0, 0}; // min, mag, wrap s, wrap t last set on it
    };
    struct Name {
        uint64_t content = 0;
        uint64_t changed = 0; // the frame of its last change of content
        int changes = 0;      // in a row, each within kChangingFrames of the one before
        bool counted = false;
    };

    bool submit(const GlFunctions& gl, uint64_t key, float detail);
    void collect(const GlFunctions& gl);
    GLuint upload(const GlFunctions& gl, const TextureImage& image);
    void startWorker();
    static void work(std::shared_ptr<Shared> shared);
    void say(const char* what, int& count);

    std::shared_ptr<Shared> mShared;
    int mWorkerPid = 0; // the process the worker runs in: a forked child starts its own
    std::unordered_map<uint64_t, Entry> mEntries;
    std::unordered_map<GLuint, Name> mNames;
    Counts mCounts;
    static bool sWait;
};

} // namespace nprgl::styles
