#include "frame/LiveExport.h"

#include "capture/Metadata.h"
#include "common/KeyValue.h"
#include "common/Log.h"
#include "common/ProcessName.h"
#include "frame/FrameExport.h"
#include "shim/Context.h"

#include <cstdlib>
#include <filesystem>

namespace nprgl {

LiveExport* LiveExport::instance()
{
    static LiveExport* exporter = []() -> LiveExport* {
        const char* spec = std::getenv("NPRGL_EXPORT");
        if (!spec || !*spec) return nullptr;
        KeyValueList pairs;
        std::string error, dir = ".", format = "obj";
        FrameSet frames;
        bool haveFrame = false;
        if (!parseKeyValues(spec, ';', pairs, error)) {
            NPRGL_ERROR("NPRGL_EXPORT: %s; no export", error.c_str());
            return nullptr;
        }
        for (const auto& [key, value] : pairs) {
            if (key == "frame" || key == "frames") {
                if (!FrameSet::parse(value, frames, error)) {
                    NPRGL_ERROR("NPRGL_EXPORT: %s; no export", error.c_str());
                    return nullptr;
                }
                haveFrame = true;
            } else if (key == "dir") {
                dir = value;
            } else if (key == "format" && (value == "obj" || value == "ply" || value == "off")) {
                format = value;
            } else {
                NPRGL_ERROR("NPRGL_EXPORT: unknown key or value '%s=%s' (use "
                            "frame=N;dir=D;format=obj|ply|off); no export",
                            key.c_str(), value.c_str());
                return nullptr;
            }
        }
        if (!haveFrame) {
            NPRGL_ERROR("NPRGL_EXPORT needs frame=N (e.g. frame=10;dir=out); no export");
            return nullptr;
        }
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        return new LiveExport(std::move(frames), dir, format); // lives until exit
    }();
    return exporter;
}

LiveExport::LiveExport(FrameSet frames, std::string dir, std::string format)
    : mFrames(std::move(frames)), mDir(std::move(dir)), mFormat(std::move(format))
{
}

const std::vector<uint8_t>* LiveExport::Blobs::blob(uint64_t hash, std::string& error)
{
    auto it = stored.find(hash);
    if (it != stored.end()) return &it->second;
    error = "missing blob";
    return nullptr;
}

uint64_t LiveExport::putBlob(const Context&, const void* data, size_t size)
{
    uint64_t hash = capture::hashBlob(data, size);
    std::lock_guard lock(mMutex);
    if (!mDone && !mBlobs.stored.count(hash)) {
        const uint8_t* p = static_cast<const uint8_t*>(data);
        mBlobs.stored.emplace(hash, std::vector<uint8_t>(p, p + size));
    }
    return hash;
}

bool LiveExport::writeFrame(const Context& ctx, uint64_t frame, const uint8_t* calls,
                            size_t size)
{
    std::lock_guard lock(mMutex);
    if (mDone) return false;
    if (!mContext) mContext = ctx.serial();
    if (ctx.serial() != mContext) return true;
    std::string error;
    if (!mTracker.runFrame(calls, size, &mBlobs, error)) {
        NPRGL_ERROR("export: frame %llu: %s; no export", static_cast<unsigned long long>(frame),
                    error.c_str());
        mDone = true;
        return false;
    }
    if (mFrames.contains(frame)) {
        std::string path = mDir + "/" + processName() + "_" +
                           std::to_string(frame) + "." + mFormat;
        size_t objects = 0;
        if (exportFrame(mReconstructor, mTracker.frameBatches(), ExportSpace::Eye, path, error,
                        &objects)) {
            NPRGL_INFO("exported frame %llu: %zu objects to %s",
                       static_cast<unsigned long long>(frame), objects, path.c_str());
        } else {
            NPRGL_ERROR("export of frame %llu: %s", static_cast<unsigned long long>(frame),
                        error.c_str());
        }
    }
    if (frame >= mFrames.last()) {
        mDone = true;
        mBlobs.stored.clear();
        return false;
    }
    return true;
}

} // namespace nprgl
