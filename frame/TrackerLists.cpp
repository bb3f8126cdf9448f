// Display lists: compiling, calling and what a list would draw (dlist.c's part of the tracker).
#include "frame/StateTracker.h"

#include "frame/TrackerGl.h"

#include "common/Log.h"
#include "stream/Opcodes.h"

#include <algorithm>

namespace nprgl {

using namespace tracker;

bool StateTracker::mayLayerList(GLuint list) const
{
    bool anyBatch = false;
    return mayLayer(GL_TRIANGLES) && listHoldable(list, anyBatch) && anyBatch;
}

bool StateTracker::wouldHoldList(GLuint list) const
{
    bool anyBatch = false;
    return wouldHold(GL_TRIANGLES) && listHoldable(list, anyBatch) && anyBatch &&
           !listDraws(list).blendsLeft;
}

const char* StateTracker::listUnstylable(GLuint list) const
{
    if (const char* why = unstylableState()) return why;
    bool anyBatch = false;
    if (!listHoldable(list, anyBatch)) {
        return "display lists that also draw lines, points, bitmaps or pixels";
    }
    if (anyBatch && listDraws(list).blendsLeft) return kListBlendsLeft;
    return nullptr; // holdable, or no polygons at all (nothing to count)
}

const char* StateTracker::listsUnstylable(GLsizei n, GLenum type, const void* lists) const
{
    const uint8_t* p = static_cast<const uint8_t*>(lists);
    // 2D drawing (text from font lists, most often) is not counted: no walk over its lists.
    if (!p || n <= 0 || !is3D()) return nullptr;
    bool anyBatch = false, holdable = true, blendsLeft = false;
    for (GLsizei i = 0; i < std::min<GLsizei>(n, 4096); ++i) {
        const GLuint list = mListBase + listId(type, p, i);
        bool ignored = false;
        holdable = listHoldable(list, ignored) && holdable;
        const ListDraws drawn = listDraws(list); // its batches and those of the lists it calls
        anyBatch = anyBatch || drawn.textured + drawn.untextured > 0;
        blendsLeft = blendsLeft || drawn.blendsLeft;
    }
    if (!anyBatch) return nullptr;
    if (const char* why = unstylableState()) return why;
    if (n > 4096) return "glCallLists of more than 4096 lists";
    if (!holdable) return "display lists that also draw lines, points, bitmaps or pixels";
    return blendsLeft ? kListBlendsLeft : nullptr;
}

bool StateTracker::listHoldable(GLuint list, bool& anyBatch) const
{
    // Breadth-first over the lists it calls; cycles and depth bounded like the driver's.
    std::vector<GLuint> pending{list};
    for (size_t i = 0; i < pending.size() && i < 64; ++i) {
        auto it = mLists.find(pending[i]);
        if (it == mLists.end()) continue;
        if (it->second.otherDraws) return false;
        anyBatch = anyBatch || !it->second.batches.empty();
        pending.insert(pending.end(), it->second.calls.begin(), it->second.calls.end());
    }
    return true;
}

StateTracker::ListDraws StateTracker::listDraws(GLuint list) const
{
    struct State {
        bool texture2D;
        GLuint bound; // unit 0's 2D texture
        bool blend;
        GLenum src, dst;
    };
    struct Walk {
        const StateTracker& t;
        ListDraws out;
        State now;
        int unit;
        std::vector<State> saved; // glPushAttrib inside the lists
        size_t work = 0;
        void run(GLuint id, int depth)
        {
            auto it = t.mLists.find(id);
            if (it == t.mLists.end() || depth >= 64) return;
            for (const ListItem& item : it->second.items) {
                if (++work > kListWorkLimit) return;
                if (item.batch >= 0) {
                    const size_t n = it->second.batches[size_t(item.batch)].vertices.size();
                    const bool on = now.texture2D && t.sceneTexture(now.bound) != 0;
                    (on ? out.textured : out.untextured) += n;
                    out.blendsLeft = out.blendsLeft ||
                                     (changesPixels(now.blend, now.src, now.dst) &&
                                      !byAlpha(now.blend, now.src, now.dst));
                    continue;
                }
                step(item.call, depth);
            }
        }
        void step(const std::vector<uint8_t>& call, int depth)
        {
            CallReader r(call.data(), call.size(), t.mBlobs, t.mOpcodes);
            const uint16_t opcode = r.opcode();
            if (opcode == op::glEnable || opcode == op::glDisable) {
                const GLenum cap = r.get<GLenum>();
                const bool on = opcode == op::glEnable;
                if (r.ok() && cap == GL_TEXTURE_2D && unit == 0) now.texture2D = on;
                if (r.ok() && cap == GL_BLEND) now.blend = on;
            } else if (opcode == op::glBindTexture) {
                const GLenum target = r.get<GLenum>();
                const GLuint texture = r.get<GLuint>();
                if (r.ok() && target == GL_TEXTURE_2D && unit == 0) now.bound = texture;
            } else if (opcode == op::glActiveTexture) {
                const GLenum u = r.get<GLenum>();
                if (r.ok()) unit = int(u) - int(GL_TEXTURE0);
            } else if (opcode == op::glBlendFunc || opcode == op::glBlendFuncSeparate) {
                const GLenum src = r.get<GLenum>();
                const GLenum dst = r.get<GLenum>();
                if (r.ok()) {
                    now.src = src;
                    now.dst = dst;
                }
            } else if (opcode == op::glPushAttrib) {
                saved.push_back(now);
            } else if (opcode == op::glPopAttrib && !saved.empty()) {
                now = saved.back();
                saved.pop_back();
            } else if (opcode == op::glCallList) {
                const GLuint inner = r.get<GLuint>();
                if (r.ok()) run(inner, depth + 1);
            }
        }
    };
    const AttribState& a = mAttrib;
    Walk walk{*this, {}, {a.texture2D, mBoundTexture, a.blend, a.blendSrc, a.blendDst},
              mActiveUnit, {}};
    walk.run(list, 0);
    return walk.out;
}

void StateTracker::newList(GLuint list, GLenum mode)
{
    if (mCompiling || list == 0) return; // GL_INVALID_OPERATION / GL_INVALID_VALUE
    mCompiling = true;
    mCompileAndExecute = mode == GL_COMPILE_AND_EXECUTE;
    mCompilingList = list;
    mCompiled = List();
    mListSetsColor = mListSetsNormal = mListSetsTexCoord = false;
}

void StateTracker::endList()
{
    if (!mCompiling) return;
    mCompiling = false;
    mLists[mCompilingList] = std::move(mCompiled);
    mCompiled = List();
}

void StateTracker::callList(GLuint list)
{
    if (mCompiling) mCompiled.calls.push_back(list); // executed now: GL_COMPILE_AND_EXECUTE
    // A list held back is held as a whole (the compositor masked the whole glCallList).
    const bool top = mHoldingList == 0 && mPassingList == 0 && mCallDepth == 0;
    const bool hold = mHolding && top && wouldHoldList(list);
    const bool pass = top && !hold;
    mHoldingList += hold;
    mPassingList += pass;
    if (mCallDepth == 0) mListWork = 0;
    callListBody(list);
    mPassingList -= pass;
    mHoldingList -= hold;
}

void StateTracker::callLists(GLsizei n, GLenum type, const void* lists)
{
    const bool top = mHoldingList == 0 && mPassingList == 0 && mCallDepth == 0;
    const bool hold = mHolding && top && wouldHoldLists(n, type, lists);
    if (!hold) otherDraw(); // text, typically
    const bool pass = top && !hold;
    mHoldingList += hold;
    mPassingList += pass;
    if (mCallDepth == 0) mListWork = 0;
    const uint8_t* p = static_cast<const uint8_t*>(lists);
    for (GLsizei i = 0; p && i < n; ++i) {
        const GLuint list = mListBase + listId(type, p, i);
        if (mCompiling) mCompiled.calls.push_back(list); // GL_COMPILE_AND_EXECUTE
        callListBody(list);
    }
    mPassingList -= pass;
    mHoldingList -= hold;
}

bool StateTracker::wouldHoldLists(GLsizei n, GLenum type, const void* lists) const
{
    const uint8_t* p = static_cast<const uint8_t*>(lists);
    if (!p || n <= 0 || n > 4096 || !wouldHold(GL_TRIANGLES)) return false;
    // Lists of state only (a material, a transform) go along with the ones that draw.
    bool anyBatch = false;
    for (GLsizei i = 0; i < n; ++i) {
        const GLuint list = mListBase + listId(type, p, i);
        if (!listHoldable(list, anyBatch) || listDraws(list).blendsLeft) return false;
    }
    return anyBatch;
}

void StateTracker::callListBody(GLuint list)
{
    auto it = mLists.find(list);
    // GL_MAX_LIST_NESTING is 64: a list that calls itself stops there, as in the driver.
    if (it == mLists.end() || mCallDepth >= 64) return;
    const List& body = it->second;
    mListWork += body.items.size() + 1;
    if (mListWork > kListWorkLimit) {
        if (!mListWorkSaid) {
            NPRGL_WARN("a display list runs more than %llu list items in one call (lists calling "
                       "themselves over and over): nprgl stops following it there, so what the "
                       "rest would draw is not styled",
                       static_cast<unsigned long long>(kListWorkLimit));
            mListWorkSaid = true;
        }
        return;
    }
    ++mCallDepth;
    ++mListDepth;
    const bool callerNormal = currentNormalCounts(); // before the list's draws clear it
    for (const ListItem& item : body.items) {
        if (item.batch >= 0) {
            const TrackedBatch& compiled = body.batches[size_t(item.batch)];
            TrackedBatch batch;
            batch.vertices = takeVertices();
            batch.vertices.assign(compiled.vertices.begin(), compiled.vertices.end());
            batch.mode = compiled.mode;
            // The driver draws a list's quads as indexed ones (reconstruct::QuadCut).
            batch.quadCut = reconstruct::QuadCut::V1V3;
            batch.hasNormals = compiled.hasNormals;
            batch.materials = compiled.materials;
            batch.beginMaterial = compiled.beginMaterial;
            batch.beginAmbient = compiled.beginAmbient;
            const List::Inherits& from = body.inherits[size_t(item.batch)];
            if (from.normal) batch.hasNormals = batch.hasNormals || callerNormal;
            // What the list did not set itself comes from the state at this call.
            if (from.color || from.normal || from.texcoord ||
                batch.hasNormals != compiled.hasNormals) {
                for (TrackedVertex& v : batch.vertices) {
                    if (from.color) v.color = mCurrent.color;
                    if (from.normal) v.normal = mCurrent.normal;
                    if (from.texcoord) v.texcoord = mCurrent.texcoord;
                    v.hasNormal = batch.hasNormals;
                }
            }
            emit(std::move(batch));
        } else {
            std::string ignored;
            runCalls(item.call.data(), item.call.size(), false, ignored);
        }
    }
    --mListDepth;
    --mCallDepth;
}

void StateTracker::deleteLists(GLuint list, GLsizei range)
{
    for (GLsizei i = 0; i < range; ++i) mLists.erase(list + GLuint(i));
}

} // namespace nprgl
