#include "capture/ByteWriter.h"
#include "capture/CaptureReader.h"
#include "capture/CaptureWriter.h"
#include "capture/Format.h"
#include "capture/ReadReport.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <new>
#include <thread>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace nprgl;
using namespace nprgl::capture;

// The largest single operator new request since the last reset: a reader fed a hostile length
// must not try to allocate it.
namespace {
std::atomic<size_t> gLargestAllocation{0};
}

void* operator new(size_t size)
{
    size_t seen = gLargestAllocation.load(std::memory_order_relaxed);
    while (size > seen && !gLargestAllocation.compare_exchange_weak(seen, size)) {
    }
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
// noinline: GCC would otherwise see free() on a pointer from operator new and warn.
__attribute__((noinline)) void operator delete(void* p) noexcept
{
    std::free(p);
}
__attribute__((noinline)) void operator delete(void* p, size_t) noexcept
{
    std::free(p);
}

namespace {

struct Frame {
    uint32_t contextId;
    uint64_t number;
    std::vector<uint8_t> calls;
};

struct Sample {
    Metadata meta;
    std::vector<Frame> frames;
    std::map<BlobHash, std::vector<uint8_t>> blobs;
    std::vector<CallCounts> countVersions; // every table written, in order
};

Metadata sampleMetadata()
{
    Metadata meta;
    meta.program = "glxgears";
    meta.commandLine = {"glxgears", "-info", ""};
    meta.glVendor = "Mesa";
    meta.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    meta.glVersion = "4.5 (Compatibility Profile) Mesa 22.3.6";
    meta.width = 300;
    meta.height = -1; // any int survives
    meta.pid = 4242;
    meta.startTimeUnix = 1700000000;
    meta.extra = {{"style", "toon"}, {"empty", ""}};
    meta.opcodeNames = {"glNewList", "glEndList", "glSomethingLater"};
    return meta;
}

// Deterministic bytes; compressible ones look like a call stream, the others are noise.
std::vector<uint8_t> makeBytes(uint32_t seed, size_t size, bool compressible)
{
    std::vector<uint8_t> out(size);
    uint32_t x = seed * 2654435761u + 1;
    for (size_t i = 0; i < size; ++i) {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        out[i] = compressible ? uint8_t((i % 16 < 12) ? i % 7 : x & 3) : uint8_t(x);
    }
    return out;
}

std::vector<uint8_t> readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void writeFile(const std::string& path, const uint8_t* data, size_t size)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
}

void writeFile(const std::string& path, const std::vector<uint8_t>& data)
{
    writeFile(path, data.data(), data.size());
}

// Writes frames of two contexts with blobs between them; `frames` frames in all.
Sample writeSample(CaptureWriter& writer, const std::string& path, int frames, size_t frameSize)
{
    Sample s;
    s.meta = sampleMetadata();
    std::string error;
    EXPECT_TRUE(writer.open(path, s.meta, error)) << error;
    for (int i = 0; i < frames; ++i) {
        if (i % 2 == 0) {
            std::vector<uint8_t> blob = makeBytes(100 + i, 64 + i * 8, i % 4 == 0);
            BlobHash hash = writer.putBlob(blob.data(), blob.size());
            EXPECT_EQ(hash, hashBlob(blob.data(), blob.size()));
            EXPECT_TRUE(writer.hasBlob(hash));
            s.blobs[hash] = blob;
        }
        Frame f{uint32_t(1 + i % 2), uint64_t(1 + i / 2), makeBytes(i, frameSize + i, i != 3)};
        EXPECT_TRUE(writer.writeFrame(f.contextId, f.number, f.calls.data(), f.calls.size()))
            << writer.lastError();
        s.frames.push_back(std::move(f));
        if (i == frames / 2) {
            CallCounts counts{{"glFogCoordf", uint64_t(i)}, {"glWindowPos2i", 1}};
            EXPECT_TRUE(writer.writeCallCounts(counts)) << writer.lastError();
            s.countVersions.push_back(counts);
        }
    }
    return s;
}

Sample writeClosedSample(const std::string& path, int frames = 6, size_t frameSize = 200)
{
    CaptureWriter writer;
    Sample s = writeSample(writer, path, frames, frameSize);
    std::string error;
    EXPECT_TRUE(writer.close(error)) << error;
    return s;
}

void expectSameFrames(const CaptureReader& reader, const Sample& s)
{
    ASSERT_EQ(reader.frames().size(), s.frames.size());
    for (size_t i = 0; i < s.frames.size(); ++i) {
        const auto& info = reader.frames()[i];
        EXPECT_EQ(info.contextId, s.frames[i].contextId) << i;
        EXPECT_EQ(info.frameNumber, s.frames[i].number) << i;
        EXPECT_EQ(info.rawSize, s.frames[i].calls.size()) << i;
        std::vector<uint8_t> calls;
        std::string error;
        ASSERT_TRUE(reader.readFrame(i, calls, error)) << error;
        EXPECT_EQ(calls, s.frames[i].calls) << i;
    }
}

// What any reading of a damaged copy must satisfy: it refuses, or what it returns is true:
// frames of the sample, in its order (a damaged one may be missing), and blobs of it.
void expectPrefixOrRefusal(const CaptureReader& reader, bool opened, const std::string& error,
                           const Sample& s, const std::string& where)
{
    if (!opened) {
        EXPECT_NE(error.find("offset"), std::string::npos) << where << ": " << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << where;
        return;
    }
    EXPECT_EQ(reader.metadata(), s.meta) << where;
    ASSERT_LE(reader.frames().size(), s.frames.size()) << where;
    size_t next = 0; // the first sample frame the reader's next frame may be
    for (size_t i = 0; i < reader.frames().size(); ++i) {
        while (next < s.frames.size() &&
               (reader.frames()[i].contextId != s.frames[next].contextId ||
                reader.frames()[i].frameNumber != s.frames[next].number)) {
            ++next;
        }
        ASSERT_LT(next, s.frames.size()) << where << ": frame " << i << " is not the sample's";
        std::vector<uint8_t> calls;
        std::string frameError;
        if (reader.readFrame(i, calls, frameError))
            EXPECT_EQ(calls, s.frames[next].calls) << where << " frame " << i;
        else
            EXPECT_NE(frameError.find("offset"), std::string::npos) << where << frameError;
        ++next;
    }
    // Frames missing from a scanned file are said, or lie where the damage is.
    if (reader.frames().size() < s.frames.size() && reader.recovered()) {
        EXPECT_FALSE(reader.damage().empty() && reader.incompleteEnd().empty() &&
                     reader.closed())
            << where;
    }
    for (const auto& blob : reader.blobs()) {
        auto it = s.blobs.find(blob.hash);
        ASSERT_NE(it, s.blobs.end()) << where;
        std::vector<uint8_t> data;
        std::string blobError;
        if (reader.readBlob(blob.hash, data, blobError)) {
            EXPECT_EQ(data, it->second) << where;
        }
    }
    if (!reader.callCounts().empty()) {
        bool known = false;
        for (const CallCounts& c : s.countVersions) known |= c == reader.callCounts();
        EXPECT_TRUE(known) << where;
    }
}

// The offset in the file where the first frame chunk starts (the end of META).
uint64_t firstChunkOffset(const std::vector<uint8_t>& file)
{
    ChunkHeader meta = parseChunkHeader(file.data() + kFileHeaderSize);
    return kFileHeaderSize + kChunkHeaderSize + meta.payloadSize;
}

// A header and a metadata chunk, ready for more chunks.
std::vector<uint8_t> fileStart()
{
    std::vector<uint8_t> file(kMagic, kMagic + sizeof kMagic);
    ByteWriter w(file);
    w.u32(kFormatVersion);
    w.u32(0);
    size_t start = beginChunk(file, kChunkMeta);
    encodeMetadata(sampleMetadata(), file);
    finishChunk(file, start);
    return file;
}

void rechecksum(std::vector<uint8_t>& file, size_t chunkAt)
{
    ChunkHeader h = parseChunkHeader(file.data() + chunkAt);
    std::vector<uint8_t> payload(file.begin() + long(chunkAt + kChunkHeaderSize),
                                 file.begin() + long(chunkAt + kChunkHeaderSize + h.payloadSize));
    uint64_t sum = chunkChecksum(file.data() + chunkAt, payload.data(), payload.size());
    for (int i = 0; i < 8; ++i) file[chunkAt + 16 + i] = uint8_t(sum >> (8 * i));
}

void put64(std::vector<uint8_t>& file, size_t at, uint64_t v)
{
    for (int i = 0; i < 8; ++i) file[at + i] = uint8_t(v >> (8 * i));
}

} // namespace

TEST(Capture, RoundTripsMetadataFramesBlobsAndCounts)
{
    std::string path = test::freshDir("capture") + "/round.nprgl";
    CaptureWriter writer;
    Sample s = writeSample(writer, path, 8, 300);
    // The same blob again writes nothing.
    const auto& first = *s.blobs.begin();
    EXPECT_EQ(writer.putBlob(first.second.data(), first.second.size()), first.first);
    CallCounts last{{"glFogCoordf", 99}};
    ASSERT_TRUE(writer.writeCallCounts(last));
    s.countVersions.push_back(last);
    std::string error;
    ASSERT_TRUE(writer.close(error)) << error;
    EXPECT_FALSE(writer.isOpen());

    CaptureReader reader;
    ASSERT_TRUE(reader.open(path, error)) << error;
    EXPECT_FALSE(reader.recovered());
    EXPECT_EQ(reader.warning(), "");
    EXPECT_EQ(reader.version(), kFormatVersion);
    EXPECT_EQ(reader.metadata(), s.meta);
    expectSameFrames(reader, s);
    EXPECT_EQ(reader.blobCount(), s.blobs.size());
    uint64_t blobBytes = 0;
    for (const auto& [hash, data] : s.blobs) {
        blobBytes += data.size();
        std::vector<uint8_t> back;
        ASSERT_TRUE(reader.readBlob(hash, back, error)) << error;
        EXPECT_EQ(back, data);
    }
    EXPECT_EQ(reader.blobBytes(), blobBytes);
    EXPECT_EQ(reader.callCounts(), last);
    EXPECT_EQ(reader.fileBytes(), readFile(path).size());
    std::vector<uint8_t> none;
    EXPECT_FALSE(reader.readBlob(12345, none, error));
    EXPECT_NE(error.find("no blob"), std::string::npos);
}

TEST(Capture, StoresABlobOncePerFile)
{
    std::string dir = test::freshDir("capture");
    std::vector<uint8_t> blob = makeBytes(7, 5000, true);
    uint64_t sizes[2];
    for (int copies = 1; copies <= 2; ++copies) {
        std::string path = dir + "/blob" + std::to_string(copies) + ".nprgl";
        CaptureWriter writer;
        std::string error;
        ASSERT_TRUE(writer.open(path, sampleMetadata(), error)) << error;
        for (int i = 0; i < copies; ++i) writer.putBlob(blob.data(), blob.size());
        uint8_t calls[4] = {1, 2, 3, 4};
        ASSERT_TRUE(writer.writeFrame(1, 1, calls, sizeof calls));
        for (int i = 0; i < copies; ++i) writer.putBlob(blob.data(), blob.size());
        ASSERT_TRUE(writer.close(error)) << error;
        sizes[copies - 1] = readFile(path).size();
        CaptureReader reader;
        ASSERT_TRUE(reader.open(path, error)) << error;
        EXPECT_EQ(reader.blobCount(), 1u);
        EXPECT_EQ(reader.blobBytes(), blob.size());
    }
    EXPECT_EQ(sizes[0], sizes[1]);
}

TEST(Capture, StoresIncompressibleAndEmptyFrames)
{
    std::string path = test::freshDir("capture") + "/stored.nprgl";
    CaptureWriter writer;
    std::string error;
    ASSERT_TRUE(writer.open(path, Metadata(), error)) << error;
    std::vector<uint8_t> noise = makeBytes(3, 4096, false);
    ASSERT_TRUE(writer.writeFrame(1, 1, noise.data(), noise.size()));
    ASSERT_TRUE(writer.writeFrame(1, 2, nullptr, 0));
    ASSERT_TRUE(writer.close(error)) << error;
    CaptureReader reader;
    ASSERT_TRUE(reader.open(path, error)) << error;
    EXPECT_EQ(reader.metadata(), Metadata());
    ASSERT_EQ(reader.frames().size(), 2u);
    EXPECT_EQ(reader.frames()[0].compressedSize, noise.size()); // stored, not grown
    std::vector<uint8_t> back;
    ASSERT_TRUE(reader.readFrame(0, back, error)) << error;
    EXPECT_EQ(back, noise);
    ASSERT_TRUE(reader.readFrame(1, back, error)) << error;
    EXPECT_TRUE(back.empty());
}

TEST(Capture, ReadsFramesInAnyOrderAndEachAlone)
{
    std::string path = test::freshDir("capture") + "/random.nprgl";
    Sample s = writeClosedSample(path, 40, 2000);
    std::string error;
    {
        CaptureReader reader;
        ASSERT_TRUE(reader.open(path, error)) << error;
        for (size_t i = s.frames.size(); i-- > 0;) {
            std::vector<uint8_t> calls;
            ASSERT_TRUE(reader.readFrame(i, calls, error)) << error;
            EXPECT_EQ(calls, s.frames[i].calls);
        }
        std::vector<uint8_t> calls;
        EXPECT_FALSE(reader.readFrame(40, calls, error));
        EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
    }

    // Damage frame 17 only: it is refused with its offset, every other frame still reads,
    // so no frame depends on another.
    CaptureReader intact;
    ASSERT_TRUE(intact.open(path, error)) << error;
    std::vector<uint8_t> file = readFile(path);
    uint64_t at = intact.frames()[17].offset;
    file[at + kChunkHeaderSize + kBodyHeaderSize + 5] ^= 0x10;
    writeFile(path, file);
    CaptureReader reader;
    ASSERT_TRUE(reader.open(path, error)) << error;
    EXPECT_FALSE(reader.recovered());
    ASSERT_EQ(reader.frames().size(), s.frames.size());
    for (size_t i = 0; i < s.frames.size(); ++i) {
        std::vector<uint8_t> calls;
        bool ok = reader.readFrame(i, calls, error);
        if (i == 17) {
            EXPECT_FALSE(ok);
            EXPECT_NE(error.find("offset " + std::to_string(at) + ": checksum mismatch"),
                      std::string::npos)
                << error;
            EXPECT_NE(error.find(path), std::string::npos) << error;
        } else {
            ASSERT_TRUE(ok) << error;
            EXPECT_EQ(calls, s.frames[i].calls);
        }
    }
}

TEST(Capture, ReadsOnSeveralThreads)
{
    std::string path = test::freshDir("capture") + "/threads.nprgl";
    Sample s = writeClosedSample(path, 16, 3000);
    CaptureReader reader;
    std::string error;
    ASSERT_TRUE(reader.open(path, error)) << error;
    std::atomic<int> bad{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            for (size_t i = t; i < s.frames.size() * 4; i += 3) {
                size_t f = i % s.frames.size();
                std::vector<uint8_t> calls;
                std::string e;
                if (!reader.readFrame(f, calls, e) || calls != s.frames[f].calls) ++bad;
            }
        });
    }
    for (auto& t : threads) t.join();
    EXPECT_EQ(bad.load(), 0);
}

TEST(Capture, WritesFromSeveralThreads)
{
    std::string path = test::freshDir("capture") + "/writers.nprgl";
    CaptureWriter writer;
    std::string error;
    ASSERT_TRUE(writer.open(path, sampleMetadata(), error)) << error;
    std::vector<std::thread> threads;
    for (uint32_t context = 1; context <= 3; ++context) {
        threads.emplace_back([&, context] {
            for (uint64_t n = 1; n <= 20; ++n) {
                std::vector<uint8_t> calls = makeBytes(context * 100 + uint32_t(n), 500, true);
                writer.putBlob(calls.data(), 64);
                writer.writeFrame(context, n, calls.data(), calls.size());
            }
        });
    }
    for (auto& t : threads) t.join();
    ASSERT_TRUE(writer.close(error)) << error;
    CaptureReader reader;
    ASSERT_TRUE(reader.open(path, error)) << error;
    ASSERT_EQ(reader.frames().size(), 60u);
    std::map<uint32_t, uint64_t> lastNumber;
    for (size_t i = 0; i < reader.frames().size(); ++i) {
        const auto& f = reader.frames()[i];
        EXPECT_EQ(f.frameNumber, lastNumber[f.contextId] + 1); // each stream stays in order
        lastNumber[f.contextId] = f.frameNumber;
        std::vector<uint8_t> calls;
        ASSERT_TRUE(reader.readFrame(i, calls, error)) << error;
        EXPECT_EQ(calls, makeBytes(f.contextId * 100 + uint32_t(f.frameNumber), 500, true));
    }
    EXPECT_EQ(reader.blobCount(), 60u);
}

TEST(Capture, KilledProgramLeavesAReadableFile)
{
    std::string path = test::freshDir("capture") + "/killed.nprgl";
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        CaptureWriter writer;
        writeSample(writer, path, 7, 400);
        raise(SIGKILL); // no close(), no destructors, no exit handlers
        _exit(1);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;

    CaptureWriter expected; // the same content again, to compare with
    Sample s = writeSample(expected, test::freshDir("capture") + "/same.nprgl", 7, 400);
    CaptureReader reader;
    std::string error;
    ASSERT_TRUE(reader.open(path, error)) << error;
    EXPECT_TRUE(reader.recovered());
    EXPECT_FALSE(reader.closed());
    // Ended cleanly after the last frame: not damaged, only not closed.
    EXPECT_TRUE(reader.damage().empty());
    EXPECT_EQ(reader.incompleteEnd(), "");
    EXPECT_EQ(reader.notes(), std::vector<std::string>{path + ": not closed by its recording " +
                                                       "(no index at its end): 7 frames found " +
                                                       "by scanning"});
    EXPECT_EQ(reader.metadata(), s.meta);
    expectSameFrames(reader, s);
    EXPECT_EQ(reader.blobCount(), s.blobs.size());
    EXPECT_EQ(reader.callCounts(), s.countVersions.back());
    for (const auto& [hash, data] : s.blobs) {
        std::vector<uint8_t> back;
        ASSERT_TRUE(reader.readBlob(hash, back, error)) << error;
        EXPECT_EQ(back, data);
    }
}

TEST(Capture, TruncationAtEveryOffsetYieldsAPrefix)
{
    std::string dir = test::freshDir("capture");
    std::string path = dir + "/whole.nprgl";
    Sample s = writeClosedSample(path, 6, 120);
    std::vector<uint8_t> file = readFile(path);
    ASSERT_LT(file.size(), 6000u);
    CaptureReader whole;
    std::string error;
    ASSERT_TRUE(whole.open(path, error)) << error;
    uint64_t firstChunk = firstChunkOffset(file);

    for (size_t length = 0; length <= file.size(); ++length) {
        // A new file each time: ext4 flushes to disk when a file is truncated and rewritten.
        std::string cut = dir + "/cut" + std::to_string(length) + ".nprgl";
        writeFile(cut, file.data(), length);
        CaptureReader reader;
        std::string where = "length " + std::to_string(length);
        bool ok = reader.open(cut, error);
        if (length < firstChunk) {
            EXPECT_FALSE(ok) << where;
            EXPECT_NE(error.find(cut + ": offset "), std::string::npos) << where << error;
            continue;
        }
        ASSERT_TRUE(ok) << where << ": " << error;
        EXPECT_EQ(reader.recovered(), length < file.size()) << where;
        size_t wholeFrames = 0;
        for (const auto& f : whole.frames())
            if (f.offset + kChunkHeaderSize + kBodyHeaderSize + f.compressedSize <= length)
                ++wholeFrames;
        EXPECT_EQ(reader.frames().size(), wholeFrames) << where;
        expectPrefixOrRefusal(reader, ok, error, s, where);
        for (size_t i = 0; i < reader.frames().size(); ++i) {
            std::vector<uint8_t> calls;
            EXPECT_TRUE(reader.readFrame(i, calls, error)) << where << ": " << error;
        }
        unlink(cut.c_str());
    }
}

TEST(Capture, BitFlipsAreRefusedOrYieldAPrefix)
{
    std::string dir = test::freshDir("capture");
    std::string path = dir + "/flip.nprgl";
    Sample s = writeClosedSample(path, 6, 150);
    std::vector<uint8_t> file = readFile(path);
    int refusedOpen = 0, refusedFrame = 0;
    for (size_t at = 0; at < file.size(); ++at) {
        for (int bit : {int(at % 8), int((at * 5 + 3) % 8)}) {
            std::vector<uint8_t> copy = file;
            copy[at] ^= uint8_t(1 << bit);
            CaptureReader reader;
            std::string error;
            std::string where = "flip at " + std::to_string(at) + " bit " + std::to_string(bit);
            bool ok = reader.openMemory(copy.data(), copy.size(), "flip.nprgl", error);
            expectPrefixOrRefusal(reader, ok, error, s, where);
            refusedOpen += !ok;
            for (size_t i = 0; ok && i < reader.frames().size(); ++i) {
                std::vector<uint8_t> calls;
                refusedFrame += !reader.readFrame(i, calls, error);
            }
        }
    }
    // Flips in the header and metadata refuse the file; flips in frames refuse the frame.
    EXPECT_GT(refusedOpen, 100);
    EXPECT_GT(refusedFrame, 100);
}

// A killed program's file with one damaged frame: the scan used to stop there and drop every
// frame after it without a word.
TEST(Capture, ScanSkipsADamagedChunkAndSaysWhatWasLost)
{
    std::string dir = test::freshDir("capture");
    std::string path = dir + "/whole.nprgl";
    Sample s = writeClosedSample(path, 8, 300);
    CaptureReader whole;
    std::string error;
    ASSERT_TRUE(whole.open(path, error)) << error;
    std::vector<uint8_t> file = readFile(path);
    // What a killed program leaves: everything before the index.
    uint64_t indexAt = whole.frames().back().offset + kChunkHeaderSize + kBodyHeaderSize +
                       whole.frames().back().compressedSize;
    file.resize(size_t(indexAt));
    uint64_t at = whole.frames()[3].offset;
    file[at + kChunkHeaderSize + kBodyHeaderSize + 7] ^= 0x01;
    path = dir + "/damaged.nprgl";
    writeFile(path, file);

    CaptureReader reader;
    ASSERT_TRUE(reader.open(path, error)) << error;
    EXPECT_TRUE(reader.recovered());
    EXPECT_FALSE(reader.closed());
    ASSERT_EQ(reader.damage().size(), 1u);
    const uint64_t next = at + kChunkHeaderSize + kBodyHeaderSize +
                          whole.frames()[3].compressedSize;
    EXPECT_EQ(reader.damage()[0].offset, at);
    EXPECT_EQ(reader.damage()[0].size, next - at);
    EXPECT_EQ(reader.damage()[0].message,
              path + ": offset " + std::to_string(at) +
                  ": checksum mismatch in 'FRAM' chunk (damaged file); skipped " +
                  std::to_string(next - at) + " bytes to the next whole chunk at offset " +
                  std::to_string(next));
    // Frame 3 is context 2's frame 2: the gap in that context's numbers says so.
    EXPECT_EQ(reader.missingFrames(),
              (std::vector<CaptureReader::FrameId>{{s.frames[3].contextId, s.frames[3].number}}));
    Sample rest = s;
    rest.frames.erase(rest.frames.begin() + 3);
    expectSameFrames(reader, rest);
    ReadReport report(reader);
    EXPECT_TRUE(report.damaged());
    EXPECT_EQ(report.summary(7), path + ": damaged: 7 frames read, at least 1 lost (context 2: 2)");
}

// Ten bytes inserted into a closed file: the footer no longer points at the index, and the
// scan used to stop at the first chunk that moved (reported as "not closed", 0 frames).
TEST(Capture, BytesInsertedIntoAClosedFileAreSkippedAndSaid)
{
    std::string dir = test::freshDir("capture");
    std::string path = dir + "/whole.nprgl";
    Sample s = writeClosedSample(path, 8, 300);
    CaptureReader whole;
    std::string error;
    ASSERT_TRUE(whole.open(path, error)) << error;
    const std::vector<uint8_t> file = readFile(path);
    const std::string junk = "0123456789";
    for (bool inChunk : {true, false}) {
        SCOPED_TRACE(inChunk ? "inside frame 5" : "before frame 5");
        const size_t at = size_t(whole.frames()[5].offset) + (inChunk ? 40 : 0);
        std::vector<uint8_t> copy = file;
        copy.insert(copy.begin() + long(at), junk.begin(), junk.end());
        const std::string damaged = dir + "/inserted.nprgl";
        writeFile(damaged, copy);
        CaptureReader reader;
        ASSERT_TRUE(reader.open(damaged, error)) << error;
        EXPECT_TRUE(reader.recovered());
        EXPECT_TRUE(reader.closed()); // its footer is there: damaged, not unclosed
        // The index the footer no longer finds, then the stretch skipped.
        ASSERT_EQ(reader.damage().size(), 2u) << reader.warning();
        EXPECT_NE(reader.damage()[0].message.find("the index is unusable"), std::string::npos)
            << reader.damage()[0].message;
        const uint64_t chunk = whole.frames()[5].offset;
        EXPECT_EQ(reader.damage()[1].offset, chunk);
        const uint64_t chunkSize =
            kChunkHeaderSize + kBodyHeaderSize + whole.frames()[5].compressedSize;
        EXPECT_EQ(reader.damage()[1].size, (inChunk ? chunkSize : 0) + junk.size());
        EXPECT_EQ(reader.warning().find("not closed"), std::string::npos) << reader.warning();
        Sample rest = s;
        if (inChunk) rest.frames.erase(rest.frames.begin() + 5);
        expectSameFrames(reader, rest);
        // The index found by the scan says exactly which frames are gone.
        EXPECT_TRUE(reader.knowsAllFrames());
        std::vector<CaptureReader::FrameId> lost;
        if (inChunk) lost.push_back({s.frames[5].contextId, s.frames[5].number});
        EXPECT_EQ(reader.missingFrames(), lost);
        ReadReport report(reader);
        EXPECT_EQ(report.summary(reader.frames().size()),
                  damaged + ": damaged: " + std::to_string(rest.frames.size()) +
                      " frames read, " + (inChunk ? "1 lost (context 2: 3)" : "no frame lost"));
    }
}

// A file cut inside its last chunk (a recording stopped while writing, or a cut copy) is
// said, but is not damage; bytes after a footer are.
TEST(Capture, AnIncompleteEndIsSaidAndTrailingBytesAreDamage)
{
    std::string dir = test::freshDir("capture");
    std::string path = dir + "/whole.nprgl";
    Sample s = writeClosedSample(path, 6, 300);
    CaptureReader whole;
    std::string error;
    ASSERT_TRUE(whole.open(path, error)) << error;
    std::vector<uint8_t> file = readFile(path);

    std::vector<uint8_t> cut(file.begin(), file.begin() + long(whole.frames()[5].offset + 30));
    const std::string cutPath = dir + "/cut.nprgl";
    writeFile(cutPath, cut);
    CaptureReader reader;
    ASSERT_TRUE(reader.open(cutPath, error)) << error;
    EXPECT_TRUE(reader.damage().empty()) << reader.warning();
    EXPECT_EQ(reader.incompleteEnd().rfind(cutPath + ": offset " +
                                               std::to_string(whole.frames()[5].offset) +
                                               ": the file ends inside a chunk",
                                           0),
              0u)
        << reader.incompleteEnd();
    EXPECT_EQ(reader.frames().size(), 5u);
    EXPECT_FALSE(ReadReport(reader).damaged());

    std::vector<uint8_t> longer = file;
    longer.insert(longer.end(), {'t', 'r', 'a', 'i', 'l', 'i', 'n', 'g', ' ', 'b', 'y', 't', 'e',
                                 's', ' ', 'a', 'f', 't', 'e', 'r', ' ', 'i', 't', '!', '!'});
    const std::string longPath = dir + "/long.nprgl";
    writeFile(longPath, longer);
    ASSERT_TRUE(reader.open(longPath, error)) << error;
    EXPECT_TRUE(reader.closed());
    ASSERT_EQ(reader.damage().size(), 1u) << reader.warning();
    EXPECT_EQ(reader.damage()[0].offset, file.size());
    EXPECT_NE(reader.damage()[0].message.find("nothing readable follows (25 bytes"),
              std::string::npos)
        << reader.damage()[0].message;
    expectSameFrames(reader, s);
    EXPECT_EQ(ReadReport(reader).summary(6), longPath + ": damaged: 6 frames read, no frame lost");
}

TEST(Capture, BitFlipsInAFileWithoutIndexLeaveNoHoles)
{
    std::string path = test::freshDir("capture") + "/open.nprgl";
    CaptureWriter writer;
    Sample s = writeSample(writer, path, 6, 150);
    std::vector<uint8_t> file = readFile(path); // before close: no index, no footer
    CaptureReader whole;
    std::string error;
    ASSERT_TRUE(whole.openMemory(file.data(), file.size(), "open.nprgl", error)) << error;
    ASSERT_EQ(whole.frames().size(), s.frames.size());
    for (size_t at = 0; at < file.size(); ++at) {
        std::vector<uint8_t> copy = file;
        copy[at] ^= uint8_t(1 << (at % 8));
        CaptureReader reader;
        std::string where = "flip at " + std::to_string(at);
        bool ok = reader.openMemory(copy.data(), copy.size(), "open.nprgl", error);
        expectPrefixOrRefusal(reader, ok, error, s, where);
        // A scanned file lists only chunks whose checksum held: every frame must read.
        for (size_t i = 0; ok && i < reader.frames().size(); ++i) {
            std::vector<uint8_t> calls;
            EXPECT_TRUE(reader.readFrame(i, calls, error)) << where << ": " << error;
        }
        if (ok) {
            // One damaged chunk costs one frame at most, and is said.
            EXPECT_GE(reader.frames().size() + 1, s.frames.size()) << where;
            // (The header's version field is not checksummed: 3 read as 2 or 1 reads alike.)
            const bool said = !reader.damage().empty() || !reader.incompleteEnd().empty();
            EXPECT_TRUE(said || (at >= 8 && at < 12)) << where;
        }
    }
}

// Version 1 wrote no opcode names: its META ends after the extra key/values, and its frames
// use version 1's numbering (which later builds keep as their first opcodes).
TEST(Capture, ReadsVersion1Files)
{
    std::string path = test::freshDir("capture") + "/v1.nprgl";
    Metadata meta = sampleMetadata();
    meta.opcodeNames.clear();
    std::vector<uint8_t> file(kMagic, kMagic + sizeof kMagic);
    ByteWriter w(file);
    w.u32(1);
    w.u32(0);
    size_t start = beginChunk(file, kChunkMeta);
    encodeMetadata(meta, file);
    // What version 1 wrote: everything up to the name table's count.
    file.resize(file.size() - 4);
    finishChunk(file, start);
    writeFile(path, file);

    CaptureReader reader;
    std::string error;
    ASSERT_TRUE(reader.open(path, error)) << error;
    EXPECT_EQ(reader.version(), 1u);
    EXPECT_EQ(reader.metadata(), meta);
    EXPECT_TRUE(reader.metadata().opcodeNames.empty());
}

TEST(Capture, RefusesWrongMagicFutureVersionAndEmptyFiles)
{
    std::string dir = test::freshDir("capture");
    std::string path = dir + "/bad.nprgl";
    CaptureReader reader;
    std::string error;

    EXPECT_FALSE(reader.open(dir + "/missing.nprgl", error));
    EXPECT_NE(error.find("missing.nprgl: cannot open"), std::string::npos) << error;

    writeFile(path, {});
    EXPECT_FALSE(reader.open(path, error));
    EXPECT_EQ(error, path + ": offset 0: empty file, not an nprgl capture");

    writeFile(path, {'N', 'P', 'R'});
    EXPECT_FALSE(reader.open(path, error));
    EXPECT_NE(error.find("offset 0: file is 3 bytes, too short"), std::string::npos) << error;

    unlink(path.c_str()); // the writer never overwrites what is not a capture
    writeClosedSample(path);
    std::vector<uint8_t> good = readFile(path);
    std::vector<uint8_t> bad = good;
    std::memcpy(bad.data(), "PK\3\4abcd", 8);
    writeFile(path, bad);
    EXPECT_FALSE(reader.open(path, error));
    EXPECT_EQ(error, path + ": offset 0: not an nprgl capture (bad magic)");

    bad = good;
    bad[8] = kFormatVersion + 1;
    writeFile(path, bad);
    EXPECT_FALSE(reader.open(path, error));
    EXPECT_NE(error.find(": offset 8: format version " + std::to_string(kFormatVersion + 1) +
                         " is newer"),
              std::string::npos)
        << error;

    bad = good;
    bad[8] = 0;
    writeFile(path, bad);
    EXPECT_FALSE(reader.open(path, error));
    EXPECT_NE(error.find("bad format version 0"), std::string::npos) << error;

    // A reader can be reused after a failure.
    writeFile(path, good);
    EXPECT_TRUE(reader.open(path, error)) << error;
    EXPECT_EQ(reader.frames().size(), 6u);
}

// What the reader says of each path, opened in a child that an alarm ends if an open blocks
// (a FIFO without a writer used to block forever); "" for a path it opened.
std::vector<std::string> openErrorsInAChild(const std::vector<std::string>& paths)
{
    int fds[2];
    if (pipe(fds) != 0) return {};
    pid_t child = fork();
    if (child == 0) {
        close(fds[0]);
        alarm(60); // a guard against a blocked open, never reached when the reader is right
        std::string out;
        for (const std::string& path : paths) {
            CaptureReader reader;
            std::string error;
            out += (reader.open(path, error) ? std::string() : error) + "\n";
        }
        ssize_t ignored = write(fds[1], out.data(), out.size());
        (void)ignored;
        _exit(0);
    }
    close(fds[1]);
    std::string out;
    char buffer[4096];
    for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) out.append(buffer, size_t(n));
    close(fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the reader blocked";
    std::vector<std::string> lines;
    for (size_t pos = 0, eol; (eol = out.find('\n', pos)) != std::string::npos; pos = eol + 1)
        lines.push_back(out.substr(pos, eol - pos));
    return lines;
}

TEST(Capture, SpecialFilesAreRefusedAtOnceWithTheirReason)
{
    std::string dir = test::freshDir("capture");
    const std::string fifo = dir + "/fifo.nprgl";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    const std::string plain = dir + "/plain.nprgl";
    writeClosedSample(plain);
    const std::vector<std::string> errors = openErrorsInAChild(
        {fifo, "/dev/zero", "/dev/urandom", dir, plain + "/inside.nprgl", plain});
    ASSERT_EQ(errors.size(), 6u);
    EXPECT_EQ(errors[0], fifo + ": is a FIFO (named pipe), not a capture file");
    EXPECT_EQ(errors[1], "/dev/zero: is a character device, not a capture file");
    EXPECT_EQ(errors[2], "/dev/urandom: is a character device, not a capture file");
    EXPECT_EQ(errors[3], dir + ": is a directory, not a capture file");
    // A path that cannot be opened says why (for any user, root included).
    EXPECT_EQ(errors[4], plain + "/inside.nprgl: cannot open: Not a directory");
    EXPECT_EQ(errors[5], "");
}

TEST(Capture, AnUnreadableFileSaysPermissionDenied)
{
    if (geteuid() == 0) GTEST_SKIP() << "root reads any file; the other path test covers open";
    std::string path = test::freshDir("capture") + "/secret.nprgl";
    writeClosedSample(path);
    ASSERT_EQ(chmod(path.c_str(), 0), 0);
    CaptureReader reader;
    std::string error;
    EXPECT_FALSE(reader.open(path, error));
    EXPECT_EQ(error, path + ": cannot open: Permission denied");
}

TEST(Capture, HugeDeclaredLengthsAllocateNothingLarge)
{
    const uint64_t huge = uint64_t(1) << 60;
    const size_t limit = size_t(4) << 20;
    std::string dir = test::freshDir("capture");
    std::string path = dir + "/huge.nprgl";
    CaptureReader reader;
    std::string error;

    // A metadata chunk claiming 2^60 bytes.
    std::vector<uint8_t> file = fileStart();
    put64(file, kFileHeaderSize + 8, huge);
    writeFile(path, file);
    gLargestAllocation = 0;
    EXPECT_FALSE(reader.open(path, error));
    EXPECT_EQ(error, path + ": offset 16: chunk length " + std::to_string(huge) +
                         " runs past the end of the file (" + std::to_string(file.size()) +
                         " bytes)");
    EXPECT_LT(gLargestAllocation.load(), limit);

    // Metadata counts and string lengths far beyond the chunk, with a valid checksum.
    for (size_t field : {size_t(0), size_t(12)}) {
        file = fileStart();
        put64(file, kFileHeaderSize + kChunkHeaderSize + field, 0x7fffffff);
        rechecksum(file, kFileHeaderSize);
        writeFile(path, file);
        gLargestAllocation = 0;
        EXPECT_FALSE(reader.open(path, error));
        EXPECT_NE(error.find("offset " + std::to_string(kFileHeaderSize + kChunkHeaderSize +
                                                        field)),
                  std::string::npos)
            << error;
        EXPECT_LT(gLargestAllocation.load(), limit);
    }

    // Frames claiming 2^60 and 1 GiB raw bytes behind a few stored ones (checksums valid).
    for (uint64_t raw : {huge, uint64_t(1) << 30}) {
        file = fileStart();
        size_t at = beginChunk(file, kChunkFrame);
        ByteWriter w(file);
        w.u32(1);
        w.u32(kCodecZstd);
        w.u64(1);
        w.u64(raw);
        w.bytes("0123456789", 10);
        finishChunk(file, at);
        writeFile(path, file);
        gLargestAllocation = 0;
        ASSERT_TRUE(reader.open(path, error)) << error;
        EXPECT_TRUE(reader.frames().empty());
        EXPECT_NE(reader.warning().find("offset " + std::to_string(at) + ": impossible frame"),
                  std::string::npos)
            << reader.warning();
        EXPECT_LT(gLargestAllocation.load(), limit);
    }

    // An index claiming 2^60 frames, and one whose frame entry claims 2^60 bytes: the index
    // is refused and the file scanned instead.
    std::string good = dir + "/good.nprgl";
    Sample s = writeClosedSample(good);
    for (int variant = 0; variant < 3; ++variant) {
        file = readFile(good);
        uint64_t indexAt = 0;
        for (int i = 0; i < 8; ++i)
            indexAt |= uint64_t(file[file.size() - 8 + i]) << (8 * i);
        size_t payload = size_t(indexAt + kChunkHeaderSize);
        if (variant == 0) put64(file, payload, huge);                     // frame count
        if (variant == 1) put64(file, payload + 8, huge);                 // blob count
        if (variant == 2) put64(file, payload + kIndexHeaderSize + 32, huge); // raw size
        rechecksum(file, size_t(indexAt));
        writeFile(path, file);
        gLargestAllocation = 0;
        ASSERT_TRUE(reader.open(path, error)) << error;
        EXPECT_TRUE(reader.recovered());
        EXPECT_NE(reader.warning().find("the file was read by scanning instead"), std::string::npos)
            << reader.warning();
        expectSameFrames(reader, s);
        EXPECT_LT(gLargestAllocation.load(), limit);
    }

    // A call count table claiming 2^31 names.
    file = fileStart();
    size_t at = beginChunk(file, kChunkCounts);
    ByteWriter w(file);
    w.u32(0x80000000u);
    w.string("glFoo");
    w.u64(1);
    finishChunk(file, at);
    writeFile(path, file);
    gLargestAllocation = 0;
    ASSERT_TRUE(reader.open(path, error)) << error;
    EXPECT_TRUE(reader.callCounts().empty());
    EXPECT_NE(reader.warning().find("call name count 2147483648 cannot fit"), std::string::npos)
        << reader.warning();
    EXPECT_LT(gLargestAllocation.load(), limit);
}

TEST(Capture, ChildAfterForkOpensItsOwnFile)
{
    std::string dir = test::freshDir("capture");
    std::string parentPath = dir + "/parent.nprgl", childPath = dir + "/child.nprgl";
    CaptureWriter writer;
    std::string error;
    ASSERT_TRUE(writer.open(parentPath, sampleMetadata(), error)) << error;
    uint8_t calls[3] = {9, 8, 7};
    ASSERT_TRUE(writer.writeFrame(1, 1, calls, sizeof calls));
    EXPECT_FALSE(writer.ownedByOtherProcess());
    uint64_t before = readFile(parentPath).size();

    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // No gtest assertions in the child: it exits with the number of the first failed check.
        int step = 0, failed = 0;
        auto check = [&](bool ok) {
            ++step;
            if (!ok && !failed) failed = step;
        };
        std::string e;
        check(writer.isOpen());
        check(writer.ownedByOtherProcess());
        check(!writer.writeFrame(1, 2, calls, sizeof calls));
        check(!writer.hasBlob(writer.putBlob(calls, 2)));
        check(!writer.close(e)); // leaves the parent's file alone
        check(e.find("belongs to process") != std::string::npos);
        check(!writer.isOpen());
        check(writer.open(childPath, sampleMetadata(), e));
        check(!writer.ownedByOtherProcess());
        check(writer.writeFrame(1, 1, calls, sizeof calls));
        check(writer.close(e));
        _exit(failed);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_FALSE(writer.ownedByOtherProcess());
    EXPECT_EQ(readFile(parentPath).size(), before);
    ASSERT_TRUE(writer.writeFrame(1, 2, calls, sizeof calls)) << writer.lastError();
    ASSERT_TRUE(writer.close(error)) << error;

    CaptureReader reader;
    ASSERT_TRUE(reader.open(parentPath, error)) << error;
    EXPECT_FALSE(reader.recovered());
    ASSERT_EQ(reader.frames().size(), 2u);
    EXPECT_EQ(reader.frames()[1].frameNumber, 2u);
    ASSERT_TRUE(reader.open(childPath, error)) << error;
    EXPECT_FALSE(reader.recovered());
    EXPECT_EQ(reader.frames().size(), 1u);
}

TEST(Capture, WriterReportsErrorsAndStopsAtAFullDisk)
{
    std::string dir = test::freshDir("capture");
    CaptureWriter writer;
    std::string error;
    EXPECT_FALSE(writer.open(dir + "/no/such/dir.nprgl", sampleMetadata(), error));
    EXPECT_NE(error.find("/no/such/dir.nprgl: cannot create"), std::string::npos) << error;
    uint8_t calls[1] = {0};
    EXPECT_FALSE(writer.writeFrame(1, 1, calls, 1));
    EXPECT_NE(writer.lastError().find("no capture file is open"), std::string::npos);
    EXPECT_FALSE(writer.close(error));

    Metadata tooLong = sampleMetadata();
    tooLong.glRenderer.assign(kMaxStringSize + 1, 'x');
    EXPECT_FALSE(writer.open(dir + "/long.nprgl", tooLong, error));
    EXPECT_NE(error.find("GL renderer is"), std::string::npos) << error;

    // A file size limit stands in for a full disk: the writer stops, and the file still
    // reads back up to the last frame it reported written.
    std::string path = dir + "/full.nprgl";
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        signal(SIGXFSZ, SIG_IGN);
        rlimit limit{20000, 20000};
        setrlimit(RLIMIT_FSIZE, &limit);
        CaptureWriter w;
        std::string e;
        if (!w.open(path, sampleMetadata(), e)) _exit(255);
        int written = 0;
        for (int i = 0; i < 100; ++i) {
            std::vector<uint8_t> frame = makeBytes(i, 1500, false);
            if (!w.writeFrame(1, uint64_t(i + 1), frame.data(), frame.size())) break;
            ++written;
        }
        uint8_t small[1] = {1};
        bool stopped = !w.writeFrame(1, 1000, small, 1) &&
                       w.lastError().find("write failed at offset") != std::string::npos;
        _exit(stopped ? written : 254);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    int written = WEXITSTATUS(status);
    ASSERT_LT(written, 100);
    ASSERT_GT(written, 5);
    CaptureReader reader;
    ASSERT_TRUE(reader.open(path, error)) << error;
    EXPECT_TRUE(reader.recovered());
    // The writer cut its partial chunk off: not damaged, only not closed.
    EXPECT_TRUE(reader.damage().empty()) << reader.warning();
    EXPECT_EQ(reader.incompleteEnd(), "");
    ASSERT_EQ(reader.frames().size(), size_t(written));
    std::vector<uint8_t> back;
    ASSERT_TRUE(reader.readFrame(size_t(written - 1), back, error)) << error;
    EXPECT_EQ(back, makeBytes(written - 1, 1500, false));
}

// The writer used to open with O_TRUNC: whatever was at the path was gone before anything
// was checked, and a FIFO blocked the open until a reader came.
TEST(Capture, WriterNeverOverwritesWhatIsNotACapture)
{
    std::string dir = test::freshDir("capture");
    CaptureWriter writer;
    std::string error;
    const std::string text = dir + "/notes.txt";
    writeFile(text, std::vector<uint8_t>{'n', 'o', 't', 'e', 's', '\n'});
    std::string why;
    EXPECT_EQ(CaptureWriter::checkTarget(text, why), CaptureWriter::Target::Other);
    EXPECT_FALSE(writer.open(text, sampleMetadata(), error));
    EXPECT_EQ(error, text + ": exists and is not an nprgl capture; it is never overwritten");
    EXPECT_EQ(readFile(text), (std::vector<uint8_t>{'n', 'o', 't', 'e', 's', '\n'}));

    const std::string capture = dir + "/old.nprgl";
    writeClosedSample(capture, 2);
    const std::vector<uint8_t> old = readFile(capture);
    EXPECT_EQ(CaptureWriter::checkTarget(capture, why), CaptureWriter::Target::Capture);
    EXPECT_FALSE(writer.open(capture, sampleMetadata(), error, false));
    EXPECT_EQ(error, capture + ": an nprgl capture is there; not replaced");
    EXPECT_EQ(readFile(capture), old);
    ASSERT_TRUE(writer.open(capture, sampleMetadata(), error, true)) << error;
    ASSERT_TRUE(writer.close(error)) << error;
    EXPECT_LT(readFile(capture).size(), old.size()); // replaced: no frames now

    const std::string empty = dir + "/empty.nprgl";
    writeFile(empty, {});
    EXPECT_EQ(CaptureWriter::checkTarget(empty, why), CaptureWriter::Target::Free);
    ASSERT_TRUE(writer.open(empty, sampleMetadata(), error, false)) << error;
    ASSERT_TRUE(writer.close(error)) << error;

    const std::string fifo = dir + "/fifo.nprgl";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    pid_t child = fork(); // an alarm ends it if the open blocks
    ASSERT_GE(child, 0);
    if (child == 0) {
        alarm(60);
        CaptureWriter w;
        std::string e;
        const bool refused =
            !w.open(fifo, sampleMetadata(), e) &&
            e == fifo + ": is a FIFO (named pipe); a capture is written only to a regular file";
        const bool dirRefused = !w.open(dir, sampleMetadata(), e) &&
                                e.find("is a directory") != std::string::npos;
        _exit(refused && dirRefused ? 0 : 1);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "blocked or not refused";
}
