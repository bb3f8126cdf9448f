#include "styles/textures/AbstractTextures.h"

#include "common/Log.h"
#include "styles/ObjectNames.h"
#include "styles/textures/GlTexture.h"
#include "styles/textures/TextureAbstraction.h"

#include <cmath>
#include <csignal>
#include <pthread.h>
#include <thread>
#include <unistd.h>

namespace nprgl::styles {

bool AbstractTextures::sWait = false;

namespace {

// One key per content and detail (in hundredths: a slider's small steps share a result).
uint64_t keyOf(uint64_t content, float detail)
{
    const uint64_t steps = uint64_t(std::lround(double(detail) * 100.0));
    uint64_t k = content ^ (steps + 0x9E3779B97F4A7C15ull + (content << 6) + (content >> 2));
    return k == 0 ? 1 : k;
}

// Level 0 of the bound texture as the shaders sample it, RGBA8. Read as GL_RGBA, GL gives a
// luminance texture's L in red alone and an intensity texture's I in red alone (GL 2.1 table
// 6.1): neverball's grey ball came back red. Those are read by their own channels and spread.
void readLevel0(const GlFunctions& gl, TextureImage& image)
{
    GLint luminance = 0, intensity = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &luminance);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTENSITY_SIZE, &intensity);
    const size_t texels = size_t(image.width) * size_t(image.height);
    // The compositor's baseline has no pack buffer and GL's pack alignment (4): the rows of
    // RGBA8 fit it; the one- and two-byte reads below are made with alignment 1.
    if (luminance <= 0 && intensity <= 0) {
        gl.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
        return;
    }
    const int channels = intensity > 0 ? 1 : 2;
    std::vector<uint8_t> read(texels * size_t(channels));
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.GetTexImage(GL_TEXTURE_2D, 0, intensity > 0 ? GL_RED : GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE,
                   read.data());
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    for (size_t i = 0; i < texels; ++i) {
        const uint8_t value = read[i * size_t(channels)];
        const uint8_t alpha = channels == 1 ? value : read[i * 2 + 1];
        uint8_t* out = &image.pixels[i * 4];
        out[0] = out[1] = out[2] = value;
        out[3] = alpha;
    }
}

} // namespace

AbstractTextures::AbstractTextures() : mShared(std::make_shared<Shared>()) {}

AbstractTextures::~AbstractTextures()
{
    std::lock_guard lock(mShared->mutex);
    mShared->stop = true;
    mShared->jobs.clear();
    mShared->wake.notify_all();
}

void AbstractTextures::setWait(bool wait) { sWait = wait; }

std::string AbstractTextures::Counts::describe() const
{
    return std::to_string(abstracted) +
           " abstracted; left as the program's: " + std::to_string(unknownContent) +
           " of unknown content, " + std::to_string(changing) + " changing, " +
           std::to_string(tooLarge) + " too large";
}

void AbstractTextures::say(const char* what, int& count)
{
    if (count++ == 0) NPRGL_INFO("textures as drawings: %s", what);
}

GLuint AbstractTextures::substitute(const GlFunctions& gl, GLuint texture, uint64_t content,
                                    float detail, uint64_t frame)
{
    if (!(detail < 1.0f) || texture == 0) return 0;
    collect(gl);
    Name& name = mNames[texture];
    // Left as the program's: each name counted once, under its first reason.
    auto leave = [&](const char* why, int& count) {
        if (!name.counted) say(why, count);
        name.counted = true;
        return GLuint(0);
    };
    if (content == 0) {
        return leave("a texture whose content is not known (rendered into or copied from the "
                     "framebuffer) is drawn as the program's",
                     mCounts.unknownContent);
    }
    if (name.content != content) {
        if (name.content != 0) {
            name.changes = frame - name.changed <= kChangingFrames ? name.changes + 1 : 1;
        }
        name.content = content;
        name.changed = frame;
    } else if (frame - name.changed > kChangingFrames) {
        name.changes = 0; // it has held still: a drawing again
    }
    if (name.changes >= kChangesAllowed) {
        return leave("a texture whose content keeps changing (video, animation) is drawn as "
                     "the program's",
                     mCounts.changing);
    }
    const uint64_t key = keyOf(content, detail);
    auto it = mEntries.find(key);
    if (it == mEntries.end()) {
        submit(gl, key, detail);
        it = mEntries.find(key);
    }
    Entry& entry = it->second;
    if (entry.state != Entry::State::Ready) return 0;
    // Sampled as the program samples its own: filters and wrapping as they are now.
    GLint now[4];
    gl.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &now[0]);
    gl.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &now[1]);
    gl.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &now[2]);
    gl.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &now[3]);
    gl.BindTexture(GL_TEXTURE_2D, entry.texture);
    const GLenum names[4] = {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S,
                             GL_TEXTURE_WRAP_T};
    for (int i = 0; i < 4; ++i) {
        if (entry.filters[i] != now[i]) {
            gl.TexParameteri(GL_TEXTURE_2D, names[i], now[i]);
            entry.filters[i] = now[i];
        }
    }
    return entry.texture;
}

bool AbstractTextures::submit(const GlFunctions& gl, uint64_t key, float detail)
{
    Entry& entry = mEntries[key];
    entry.state = Entry::State::Failed;
    GLint width = 0, height = 0, depthBits = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &height);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &depthBits);
    if (width <= 0 || height <= 0 || depthBits > 0) return false; // no colour image
    if (long(width) * long(height) > kMaxTexels) {
        say("a texture larger than 2048x2048 texels is drawn as the program's", mCounts.tooLarge);
        return false;
    }
    Job job{key, {}, detail};
    job.image.width = width;
    job.image.height = height;
    job.image.channels = 4;
    job.image.pixels.resize(size_t(width) * size_t(height) * 4);
    readLevel0(gl, job.image);
    entry.state = Entry::State::Pending;
    if (sWait) {
        const TextureImage done = TextureAbstraction::abstracted(job.image, detail);
        entry.texture = done.empty() ? 0 : upload(gl, done);
        entry.state = entry.texture ? Entry::State::Ready : Entry::State::Failed;
        return entry.texture != 0;
    }
    {
        std::lock_guard lock(mShared->mutex);
        mShared->jobs.push_back(std::move(job));
    }
    startWorker();
    mShared->wake.notify_all();
    return true;
}

void AbstractTextures::startWorker()
{
    if (mWorkerPid == getpid()) return;
    mWorkerPid = getpid();
    // The worker takes no signal of the program's: they stay with the threads it expects.
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &old);
    std::thread(&AbstractTextures::work, mShared).detach();
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
}

void AbstractTextures::work(std::shared_ptr<Shared> shared)
{
    std::unique_lock lock(shared->mutex);
    for (;;) {
        shared->wake.wait(lock, [&] { return shared->stop || !shared->jobs.empty(); });
        if (shared->stop) return;
        Job job = std::move(shared->jobs.front());
        shared->jobs.pop_front();
        lock.unlock();
        TextureImage result = TextureAbstraction::abstracted(job.image, job.detail);
        lock.lock();
        if (shared->stop) return;
        shared->done.emplace(job.key, std::move(result));
    }
}

void AbstractTextures::collect(const GlFunctions& gl)
{
    std::unordered_map<uint64_t, TextureImage> done;
    {
        std::lock_guard lock(mShared->mutex);
        if (mShared->done.empty()) return;
        done.swap(mShared->done);
    }
    GLint bound = 0;
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    for (auto& [key, image] : done) {
        auto it = mEntries.find(key);
        if (it == mEntries.end() || it->second.state != Entry::State::Pending) continue;
        it->second.texture = image.empty() ? 0 : upload(gl, image);
        it->second.state = it->second.texture ? Entry::State::Ready : Entry::State::Failed;
    }
    gl.BindTexture(GL_TEXTURE_2D, GLuint(bound));
}

GLuint AbstractTextures::upload(const GlFunctions& gl, const TextureImage& image)
{
    GLuint texture = 0;
    ObjectNames::reserve(gl, ObjectNames::Kind::Texture, 1, &texture);
    gl.BindTexture(GL_TEXTURE_2D, texture);
    GlTexture::resetUnpack(gl);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA,
                  GL_UNSIGNED_BYTE, image.pixels.data());
    // Mipmaps always: the program's minification filter, copied at each bind, may ask for them.
    gl.GenerateMipmap(GL_TEXTURE_2D);
    if (mCounts.abstracted++ == 0) {
        NPRGL_INFO("textures as drawings: the program's textures are drawn abstracted "
                   "(toon.texture_detail)");
    }
    return texture;
}

void AbstractTextures::destroy(const GlFunctions& gl)
{
    {
        std::lock_guard lock(mShared->mutex);
        mShared->jobs.clear();
        mShared->done.clear();
    }
    for (auto& [key, entry] : mEntries) {
        if (entry.texture && gl.DeleteTextures) gl.DeleteTextures(1, &entry.texture);
    }
    mEntries.clear();
    mNames.clear();
}

} // namespace nprgl::styles
