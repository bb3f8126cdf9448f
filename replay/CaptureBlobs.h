#pragma once

// CaptureBlobs: a capture file's blobs served to a CallReader (replay, dump, info, export).

#include "capture/CaptureReader.h"
#include "stream/CallReader.h"

#include <map>
#include <vector>

namespace nprgl {

// The blobs of a capture file for a CallReader: each read once and kept while this lives.
class CaptureBlobs : public BlobSource {
public:
    explicit CaptureBlobs(const capture::CaptureReader& reader) : mReader(reader) {}

    const std::vector<uint8_t>* blob(uint64_t hash, std::string& error) override
    {
        auto it = mCache.find(hash);
        if (it != mCache.end()) return &it->second;
        std::vector<uint8_t> data;
        if (!mReader.readBlob(hash, data, error)) return nullptr;
        return &mCache.emplace(hash, std::move(data)).first->second;
    }

private:
    const capture::CaptureReader& mReader;
    std::map<uint64_t, std::vector<uint8_t>> mCache;
};

} // namespace nprgl
