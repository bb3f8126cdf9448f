#!/usr/bin/env python3
"""Generates the call codec of the Stream from the Khronos registry.

From the same GL command list as gen_api.py, it classifies every parameter (scalar,
fixed or counted array, image, string, client-array pointer, index buffer, output) using the
registry's `len` attributes, and emits C++ for the build tree:

  nprgl_record.inc  one recording function per command: encode, then call the driver
  nprgl_decode.inc  decodeAndReplay() and decodeAndDump(): one switch over every opcode
  nprgl_enums.inc   enum names (by group where the registry gives one) for the dump

Every command gets a mode:
  record    encoded into the Stream, then the driver is called (replayed from the capture);
  query     a pure read (glGet*, glIs*): the slot stays the driver's, nothing to follow;
  readback  a read of pixels the held scene may still have to draw: a compositor barrier;
  count     a command nprgl neither follows nor records: counted by name (the capture says
            it lacks it, in which frames), a compositor barrier, then forwarded.
"""
import argparse
import re
import sys
import xml.etree.ElementTree as ET

import gen_api

# Queries: they change nothing a replay or a style needs.
QUERY_PREFIXES = ("glGet", "glIs", "glAreTexturesResident")
QUERIES = {"glCheckFramebufferStatus", "glCheckFramebufferStatusEXT", "glGetError"}
# Queries that read rendered pixels back: what is held must be drawn first.
READBACK_RE = re.compile(r"glGet(n?(Compressed)?Tex(ture)?(Sub)?Image\w*|"
                         r"QueryObject\w*|QueryBufferObject\w*|BufferSubData\w*|"
                         r"NamedBufferSubData\w*)")
# Byte arrays that drivers read as C strings as well (Mesa's glProgramStringARB runs strlen on
# it): replayed from a copy with a terminating zero after its `len` bytes.
TEXT_PARAMS = {("glProgramStringARB", "string")}
# Readbacks the recorder judges by state (Recorder::<hook>(opcode)): glReadPixels into client
# memory changes nothing a replay needs; into a pixel-pack buffer it is not captured.
READBACK_HOOKS = {"glReadPixels": "readPixels"}
# Calls whose effects cannot be replayed from their arguments: counted only.
UNCAPTURED = {
    "glRenderMode", "glFeedbackBuffer", "glSelectBuffer", "glMap1d",
    "glMap1f", "glMap2d", "glMap2f", "glMultiDrawElements",
}
# Commands that return the name of a shader or program object: the recorder follows each with
# a kCreated pseudo-call holding the name the program got, and a replay maps that name to the
# one its own driver gives (the names share one space with nprgl's own programs, which a replay
# makes before the capture's; unlike glGen* names, these cannot be chosen).
CREATES = {"glCreateProgram", "glCreateShader"}
# Parameters naming shader or program objects (the registry's class, or the ARB handle group):
# replayed through the sink's map of created names.
OBJECT_CLASSES = {"program", "shader"}
OBJECT_GROUPS = {"handleARB"}
# ARB assembly programs (glBindProgramARB ...) have names of their own, made by glGen.
ASSEMBLY_RE = re.compile(r"gl\w*Programs?\w*ARB")
# Output-only commands that are replayed with scratch memory (names come back the same).
GEN_COMMANDS = {"glGenTextures", "glGenQueries", "glGenBuffers", "glGenFramebuffers",
                "glGenRenderbuffers", "glGenProgramsARB"}
# Handled entirely by hand in Recorder (they touch client memory or mapped buffers).
SPECIAL = {"glMapBuffer", "glMapBufferRange", "glFlushMappedBufferRange", "glUnmapBuffer",
           "glInterleavedArrays"}
# Recorder hooks called before recording (state the recorder must follow).
HOOK_BEFORE = {
    "glBegin", "glDrawArrays", "glDrawElements", "glDrawRangeElements", "glArrayElement",
    "glMultiDrawArrays", "glEnableClientState", "glDisableClientState",
    "glClientActiveTexture", "glEnableVertexAttribArray", "glDisableVertexAttribArray",
    "glBindBuffer", "glBufferData", "glBufferSubData", "glPushClientAttrib",
    "glPopClientAttrib", "glDeleteBuffers", "glVertexPointer", "glNormalPointer",
    "glColorPointer", "glSecondaryColorPointer", "glFogCoordPointer", "glIndexPointer",
    "glEdgeFlagPointer", "glTexCoordPointer", "glVertexAttribPointer",
}
# Draw hooks that may refuse: the draw then goes to the driver unrecorded (nprgl could not
# follow where its arrays or indices are), also when the compositor would have held it.
HOOK_GATE = {"glDrawArrays", "glDrawElements", "glDrawRangeElements", "glMultiDrawArrays"}
# Recorder hooks called after the call is encoded (before the driver's).
HOOK_AFTER = {"glEnd"}
CLIENT_POINTERS = {
    "glVertexPointer", "glNormalPointer", "glColorPointer", "glSecondaryColorPointer",
    "glFogCoordPointer", "glIndexPointer", "glEdgeFlagPointer", "glTexCoordPointer",
    "glVertexAttribPointer",
}

SCALAR_TYPES = {
    "GLenum", "GLint", "GLfloat", "GLdouble", "GLsizei", "GLuint", "GLshort", "GLboolean",
    "GLubyte", "GLbyte", "GLushort", "GLbitfield", "GLsizeiptr", "GLintptr", "GLclampf",
    "GLclampd", "GLhandleARB",
}

FRAME_END_OPCODE = 0xFF00

# Calls a replaying sink may check before they reach the driver (which trusts counts, ranges
# and pointers): when the sink has check_<name>(decoded arguments..., [image descriptor]),
# a false return refuses the call. Image arguments all go to sink.checkImage when it has one.
CHECKED = {
    "glDrawArrays", "glDrawElements", "glDrawRangeElements", "glMultiDrawArrays",
    "glArrayElement", "glNewList", "glEndList", "glCallList", "glCallLists", "glListBase",
    "glDeleteLists", "glGenLists", "glEvalMesh1", "glEvalMesh2", "glBufferData",
    "glCopyTexImage1D", "glCopyTexImage2D", "glGenTextures", "glGenQueries", "glGenBuffers",
    "glGenFramebuffers", "glGenRenderbuffers", "glGenProgramsARB",
}

# Calls a replaying sink may issue itself, in another form: when it has issue_<name>(the
# driver's arguments), that is called instead of the driver's entry point.
ISSUED = {"glDrawRangeElements", "glViewport", "glScissor", "glCopyTexImage2D",
          "glCopyTexSubImage2D", "glBlitFramebuffer", "glClear"}


class Param:
    def __init__(self, ctype, name, length, group, cls=None):
        self.ctype, self.name, self.len, self.group = ctype, name, length, group
        self.names_object = cls in OBJECT_CLASSES or group in OBJECT_GROUPS
        self.const = ctype.startswith("const")
        self.pointer = "*" in ctype
        base = ctype.replace("const", "").replace("*", "").strip()
        self.base = base
        self.kind = None  # scalar | array | image | string | clientptr | indices | out
        self.count = None  # C++ expression (elements), with {a} standing for the arg prefix


def elemType(p):
    return "uint8_t" if p.base in ("void", "GLvoid") else p.base


def countExpr(p, params):
    """Element count of a const array parameter as a C++ expression over {a}name, or None."""
    length = p.len
    if length is None:
        return None
    if re.fullmatch(r"\d+", length):
        return length
    names = {q.name for q in params}
    m = re.fullmatch(r"(\w+)(\*(\d+))?", length)
    if m and m.group(1) in names:
        expr = f"size_t({{a}}{m.group(1)})"
        return f"{expr} * {m.group(3)}" if m.group(3) else expr
    if length == "COMPSIZE(pname)":
        return "pnameCount({a}pname)"
    if length == "COMPSIZE(n,type)":
        return "callListsBytes({a}n, {a}type)"
    return None


def classify(cmd, params, recordable):
    """Returns 'record', 'query', 'readback', 'count' or 'special', and sets each param's
    kind. recordable: the command is one nprgl means to record (GL 1.0-2.1 and
    RECORDED_EXTRA); any other is counted."""
    if cmd in SPECIAL:
        return "special"
    if READBACK_RE.fullmatch(cmd) or cmd in READBACK_HOOKS:
        return "readback"
    if cmd in QUERIES or (cmd.startswith(QUERY_PREFIXES) and cmd not in UNCAPTURED):
        return "query"
    if cmd in UNCAPTURED or not recordable:
        return "count"
    for p in params:
        if not p.pointer:
            if p.base not in SCALAR_TYPES:
                return "count"
            p.kind = "scalar"
        elif not p.const:
            if cmd in GEN_COMMANDS:
                p.kind = "out"
                p.count = "size_t({a}n)"
            else:
                return "count"
        elif cmd in CLIENT_POINTERS and p.name == "pointer":
            p.kind = "clientptr"
        elif p.len and p.len.startswith("COMPSIZE(format,type,width"):
            p.kind = "image"
            dims = p.len[len("COMPSIZE(format,type,"):-1].split(",")
            args = ", ".join(f"{{a}}{d}" for d in dims) + ", 1" * (3 - len(dims))
            p.count = f"{{a}}format, {{a}}type, {args}"
        elif p.len in ("COMPSIZE(width,height)", "COMPSIZE()"):
            # glBitmap, glPolygonStipple: bitmaps laid out by the unpack state, like images.
            p.kind = "image"
            dims = "{a}width, {a}height" if p.len == "COMPSIZE(width,height)" else "32, 32"
            p.count = f"GL_COLOR_INDEX, GL_BITMAP, {dims}, 1"
        elif p.len == "COMPSIZE(count,type)":
            p.kind = "indices"
        elif cmd.startswith("glCompressedTex") and p.name == "data":
            # Read from the pixel-unpack buffer when one is bound, like images.
            p.kind = "unpacked"
            p.count = "size_t({a}imageSize)"
        elif p.base == "GLchar" and p.len is None and p.ctype.count("*") == 1:
            p.kind = "string"
        elif p.ctype.count("*") > 1:
            if cmd == "glShaderSource":
                p.kind = "sources"
            else:
                return "count"
        else:
            p.count = countExpr(p, params)
            if p.count is None:
                return "count"
            p.kind = "text" if (cmd, p.name) in TEXT_PARAMS else "array"
    return "record"


# How each kind of parameter is written by the recorder (0) and read back by the decoder (1):
# one row per kind, so that the two sides cannot drift apart. {name} is the parameter, {n}
# its decoded variable, {count} its element count (encoder) and {dcount} (decoder).
CODEC = {
    "scalar": ("w_.put<{base}>({name});", "const {base} {n} = r.get<{base}>();"),
    "array": ("w_.putBytes({name}, {name} ? ({count}) * sizeof({elem}) : 0);",
              "const {elem}* {n} = r.getArray<{elem}>({dcount});"),
    "image": ("rec_.putImage(w_, {name}, {count});",
              "const void* {n} = r.getImage();\n"
              "        [[maybe_unused]] const CallReader::Image {n}_img = r.lastImage();"),
    "indices": ("rec_.putIndices(w_, {name}, count, type);",
                "const void* {n} = r.getImage();\n"
                "        [[maybe_unused]] const CallReader::Image {n}_img = r.lastImage();"),
    "unpacked": ("rec_.putUnpacked(w_, {name}, {count});",
                 "const void* {n} = r.getImage();\n"
                 "        [[maybe_unused]] const CallReader::Image {n}_img = r.lastImage();"),
    "string": ("w_.putString({name});", "const GLchar* {n} = r.getString();"),
    "text": ("w_.putBytes({name}, {name} ? size_t({count}) : 0);",
             "const char* {n} = r.getText({dcount});"),
    "sources": ("w_.putSources(count, {name}, length);",
                "const CallReader::Sources {n} = r.getSources(a_count);"),
    "clientptr": ("w_.put<uint64_t>(reinterpret_cast<uintptr_t>({name}));",
                  "const uint64_t {n} = r.get<uint64_t>();"),
    "out": ("", "auto {n} = sink.template scratch<{base}>({dcount});"),
}


def codecLine(p, side):
    count = p.count or ""
    return CODEC[p.kind][side].format(name=p.name, n=f"a_{p.name}", base=p.base,
                                      elem=elemType(p), count=sub(count, ""),
                                      dcount=sub(count, "a_"))


def encodingOrder(params):
    """Scalars first: array lengths may name a parameter declared after the array."""
    first = [p for p in params if p.kind in ("scalar", "clientptr")]
    return first + [p for p in params if p not in first]


def sub(expr, prefix):
    return expr.replace("{a}", prefix)


# Facts about GL commands, written here once and emitted as kOpcodeFacts (nprgl_opcodes.inc)
# for the tracker, the recorder and the compositor alike.
# - vertex: makes geometry (a vertex, a draw, a rectangle; the tracker follows no glRect*v).
#   The tracker runs it even while a list compiles, so that the list's batches are captured;
#   inside glBegin/glEnd every call is one (the tracker's own rule).
VERTEX_RE = re.compile(r"gl(Begin|End|Vertex[234][dfis]v?|ArrayElement|DrawArrays|DrawElements|"
                       r"DrawRangeElements|MultiDrawArrays|Rect[dfis])")
# - held: the compositor holds it back, recorded and not sent to the driver (the styles draw
#   it): the vertex calls and these (evaluators; glCallList, a list that may be a pass over
#   held geometry, recorded first and run once decided). Attribute calls inside a held
#   glBegin/glEnd still reach the driver (they are valid outside glBegin/glEnd too), so the
#   current colour, normal... stay the program's.
HELD_TOO_RE = re.compile(r"gl(Rect[dfis]v|EvalCoord[12][df]v?|EvalPoint[12]|CallList)")
# - immediate: GL runs it at once even inside glNewList, never compiling it (client state,
#   buffer objects, list and name management; OpenGL 2.1 section 5.4): a list that sets up
#   its own vertex arrays still draws from them while it compiles.
IMMEDIATE = {
    "glEnableClientState", "glDisableClientState", "glVertexPointer", "glNormalPointer",
    "glColorPointer", "glTexCoordPointer", "glIndexPointer", "glEdgeFlagPointer",
    "glInterleavedArrays", "glClientActiveTexture", "glPushClientAttrib", "glPopClientAttrib",
    "glPixelStorei", "glPixelStoref", "glBindBuffer", "glBufferData", "glBufferSubData",
    "glGenBuffers", "glDeleteBuffers", "glGenLists", "glDeleteLists", "glSecondaryColorPointer",
    "glFogCoordPointer", "glVertexAttribPointer", "glEnableVertexAttribArray",
    "glDisableVertexAttribArray"}
FACT_VERTEX, FACT_IMMEDIATE, FACT_HELD, FACT_INTERCEPTED = 1, 2, 4, 8
# - compositor: what the compositor does at the call (frame/CompositorInstall.cpp defines one
#   thunk macro per kind; emitted as nprgl_compositor.inc with the dispatch entries):
#   heldDraw (expression: where the draw goes, Compositor::Placement), clear (expression:
#   whether colour is cleared), barrier (held drawing is drawn first), drawing (a barrier that
#   gives the framebuffer other pixels), copyToTexture, bindFramebuffer, and own (a thunk
#   written by hand, named c_<command>).
COMPOSITOR = {
    "glBegin": ("own",), "glEnd": ("own",), "glCallList": ("own",), "glCallLists": ("own",),
    "glReadPixels": ("own",), "glRenderMode": ("own",),
    "glDrawArrays": ("heldDraw", "placeDraw(mode, true)"),
    "glDrawElements": ("heldDraw", "placeDraw(mode, true)"),
    "glDrawRangeElements": ("heldDraw", "placeDraw(mode, true)"),
    "glMultiDrawArrays": ("heldDraw", "placeDraw(mode, true)"),
    "glRectf": ("heldDraw", "placeDraw(GL_POLYGON, false)"),
    "glRectd": ("heldDraw", "placeDraw(GL_POLYGON, false)"),
    "glRecti": ("heldDraw", "placeDraw(GL_POLYGON, false)"),
    "glRects": ("heldDraw", "placeDraw(GL_POLYGON, false)"),
    "glClear": ("clear", "(mask & GL_COLOR_BUFFER_BIT) != 0"),
    "glClearBufferiv": ("clear", "buffer == GL_COLOR"),
    "glClearBufferuiv": ("clear", "buffer == GL_COLOR"),
    "glClearBufferfv": ("clear", "buffer == GL_COLOR"),
    "glClearBufferfi": ("clear", "false"),
    "glAccum": ("drawing",), "glCopyPixels": ("drawing",), "glBitmap": ("raster",),
    "glDrawPixels": ("raster",),
    "glCopyTexImage1D": ("copyToTexture",), "glCopyTexImage2D": ("copyToTexture",),
    "glCopyTexSubImage1D": ("copyToTexture",), "glCopyTexSubImage2D": ("copyToTexture",),
    "glCopyTexSubImage3D": ("copyToTexture",),
    "glFinish": ("barrier",), "glFlush": ("barrier",), "glDrawBuffer": ("barrier",),
    "glDrawBuffers": ("barrier",), "glViewport": ("barrier",), "glGenerateMipmap": ("barrier",),
    "glBindFramebuffer": ("bindFramebuffer",), "glBindFramebufferEXT": ("bindFramebuffer",),
    "glFramebufferTexture1D": ("drawing",), "glFramebufferTexture2D": ("drawing",),
    "glFramebufferTexture3D": ("drawing",), "glFramebufferTextureLayer": ("drawing",),
    "glFramebufferRenderbuffer": ("drawing",), "glBlitFramebuffer": ("drawing",),
}


def commandFacts(name, mode):
    facts = FACT_VERTEX if VERTEX_RE.fullmatch(name) else 0
    if name in IMMEDIATE:
        facts |= FACT_IMMEDIATE
    if mode == "record" and (facts & FACT_VERTEX or HELD_TOO_RE.fullmatch(name)):
        facts |= FACT_HELD
    if name in COMPOSITOR:
        facts |= FACT_INTERCEPTED
    return facts


def emitRecord(cmds):
    out = ["// Generated by shim/gen_codec.py. Do not edit.", "namespace rec {"]
    held = []
    for heldOnly in (False, True):
        if heldOnly:
            out.append("} // namespace rec")
            out.append("namespace recHeld {")
        for op, (ret, name, params, mode) in enumerate(cmds):
            if mode == "query":
                continue
            if heldOnly and not commandFacts(name, mode) & FACT_HELD:
                continue
            if heldOnly:
                held.append(name)
            out += recordFunction(op, ret, name, params, mode, heldOnly)
    out.append("} // namespace recHeld")
    out.append("inline void fillRecordingDispatch(GlDispatch& d)\n{")
    for ret, name, params, mode in cmds:
        if mode != "query":
            out.append(f"    d.{name} = &rec::{name};")
    out.append("}")
    out.append("// Held-back draws: record only.")
    out.append("inline void fillHeldDispatch(GlDispatch& d)\n{")
    for name in held:
        out.append(f"    d.{name} = &recHeld::{name};")
    out.append("}")
    return "\n".join(out) + "\n"


def paramList(params):
    """The C parameter list of a command ("GLenum mode, const void *p"; empty for none)."""
    return ", ".join(f"{p.ctype} {p.name}" if not p.ctype.endswith("*")
                     else f"{p.ctype}{p.name}" for p in params)


def recordFunction(op, ret, name, params, mode, heldOnly):
    out = []
    plist = paramList(params) or "void"
    args = ", ".join(p.name for p in params)
    call = f"gRealGl.{name}({args})"
    body = []
    if mode == "special":
        body.append(f"    return Recorder::current().{name}({args});")
    elif mode == "count":
        body.append(f"    Recorder::current().countUncaptured({op});")
        body.append(f"    return {call};")
    elif mode == "readback" and name in READBACK_HOOKS:
        body.append(f"    Recorder::current().{READBACK_HOOKS[name]}({op});")
        body.append(f"    return {call};")
    elif mode == "readback":
        body.append("    Recorder::current().readback();")
        body.append(f"    return {call};")
    else:
        body.append("    Recorder& rec_ = Recorder::current();")
        if name in HOOK_GATE:
            body.append(f"    if (!rec_.before_{name}({args})) return {call};")
        elif name in HOOK_BEFORE:
            body.append(f"    rec_.before_{name}({args});")
        body.append("    CallWriter& w_ = rec_.writer();")
        variable = any(p.kind != "scalar" for p in params)
        body.append(f"    w_.op({op});")
        if variable:
            body.append("    const size_t mark_ = w_.beginPayload();")
        for p in encodingOrder(params):
            if CODEC[p.kind][0]:
                body.append("    " + codecLine(p, 0))
        if variable:
            body.append("    w_.endPayload(mark_);")
        if name in HOOK_AFTER:
            body.append(f"    rec_.after_{name}({args});")
        if name in CREATES and not heldOnly:
            body.append(f"    const {ret} made_ = {call};")
            body.append("    rec_.created(made_);")
            body.append("    return made_;")
        else:
            body.append("    return;" if heldOnly else f"    return {call};")
    out.append(f"{ret} {name}({plist})\n{{")
    out += body
    out.append("}")
    return out


ATTRIB_RE = re.compile(
    r"gl(Vertex|Normal|Color|TexCoord|MultiTexCoord)([1-4])(b|s|i|f|d|ub|us|ui)(v?)")
NORMALIZE = {"b": "127.0f", "s": "32767.0f", "i": "2147483647.0f", "ub": "255.0f",
             "us": "65535.0f", "ui": "4294967295.0f"}


def emitTrack(cmds):
    """Tracking functions for the per-vertex attribute commands (every variant folded into
    one attrib(kind, x, y, z, w) call, as Mesa's vbo_attrib_tmp.h does), and no-ops for the
    rest; the StateTracker overrides the commands it follows by hand."""
    cmds = [c for c in cmds if c[3] == "record"]  # the tracker sees recorded calls only
    tracked = {name for _, name, _, _ in cmds if ATTRIB_RE.fullmatch(name)}
    out = ["// Generated by shim/gen_codec.py. Do not edit.", "namespace noop {"]
    for ret, name, params, _ in cmds:
        if name in tracked:
            continue
        plist = ", ".join(f"{p.ctype}" for p in params) or "void"
        out.append(f"{ret} {name}({plist}) {{ return zeroValue<{ret}>(); }}")
    out.append("} // namespace noop")
    out.append("namespace trk {")
    attribs = []
    for ret, name, params, _ in cmds:
        m = ATTRIB_RE.fullmatch(name)
        if not m:
            continue
        kind, n, t, vec = m.group(1), int(m.group(2)), m.group(3), m.group(4)
        multi = kind == "MultiTexCoord"
        values = params[1:] if multi else params
        if vec:
            comps = [f"{values[0].name}[{i}]" for i in range(n)]
        else:
            comps = [p.name for p in values]
        norm = kind in ("Color", "Normal") and t in NORMALIZE
        comps = [f"float({c}) / {NORMALIZE[t]}" if norm else f"float({c})" for c in comps]
        default = ["0.0f", "0.0f", "0.0f", "1.0f"]
        comps = comps + default[len(comps):]
        plist = paramList(params)
        if multi:
            # Every unit's coordinates: the unit a draw textures from may be any one.
            out.append(f"void {name}({plist}) {{ currentTracker().unitTexCoord("
                       f"{params[0].name}, {', '.join(comps)}); }}")
        else:
            out.append(f"void {name}({plist}) {{ currentTracker().attrib("
                       f"Attrib::{kind}, {', '.join(comps)}); }}")
        attribs.append(name)
    out.append("} // namespace trk")
    out.append("inline void fillTrackingDispatch(GlDispatch& d)\n{")
    for ret, name, params, _ in cmds:
        target = "trk" if name in attribs else "noop"
        out.append(f"    d.{name} = &{target}::{name};")
    out.append("}")
    return "\n".join(out) + "\n"


def emitOpcodes(cmds):
    out = ["// Generated by shim/gen_codec.py. Do not edit.", "namespace op {"]
    out += [f"constexpr uint16_t {name} = {i};" for i, (_, name, _, _) in enumerate(cmds)]
    out += [f"constexpr uint16_t kFrameEnd = 0x{FRAME_END_OPCODE:X};",
            f"constexpr uint16_t kArrayData = 0x{FRAME_END_OPCODE + 1:X};",
            f"constexpr uint16_t kBatchRef = 0x{FRAME_END_OPCODE + 2:X};",
            f"constexpr uint16_t kUncaptured = 0x{FRAME_END_OPCODE + 3:X};",
            f"constexpr uint16_t kCreated = 0x{FRAME_END_OPCODE + 4:X};",
            f"constexpr uint16_t kCount = {len(cmds)};",
            "} // namespace op"]
    out.append("constexpr const char* kOpcodeNames[] = {")
    out += [f'    "{name}",' for _, name, _, _ in cmds]
    out.append("};")
    out.append("constexpr bool kOpcodeRecorded[] = {")
    out += [f"    {'true' if mode == 'record' else 'false'}," for _, _, _, mode in cmds]
    out.append("};")
    out.append("// What each command is (gen_codec.py's facts): fact::kVertex,")
    out.append("// kRunsWhileCompiling, kHeld, kIntercepted (the compositor has a thunk for it).")
    out.append("namespace fact {")
    out.append(f"constexpr uint8_t kVertex = {FACT_VERTEX};")
    out.append(f"constexpr uint8_t kRunsWhileCompiling = {FACT_IMMEDIATE};")
    out.append(f"constexpr uint8_t kHeld = {FACT_HELD};")
    out.append(f"constexpr uint8_t kIntercepted = {FACT_INTERCEPTED};")
    out.append("} // namespace fact")
    out.append("constexpr uint8_t kOpcodeFacts[] = {")
    out += [f"    {commandFacts(name, mode)}, // {name}" for _, name, _, mode in cmds]
    out.append("};")
    return "\n".join(out) + "\n"


def emitCompositor(cmds):
    """The compositor's thunks (one macro call per command, by its COMPOSITOR kind) and
    fillCompositorDispatch, which points the dispatch at them."""
    out = ["// Generated by shim/gen_codec.py. Do not edit.",
           "// Included by frame/CompositorInstall.cpp, which defines the NPRGL_COMPOSITOR_*",
           "// macros and the hand-written c_<command> thunks (kind own)."]
    known = {name for _, name, _, _ in cmds}
    missing = sorted(set(COMPOSITOR) - known)
    if missing:
        raise SystemExit(f"gen_codec: COMPOSITOR names commands gl.xml lacks: {missing}")
    taken = []
    for ret, name, params, _ in cmds:
        if name not in COMPOSITOR:
            continue
        kind = COMPOSITOR[name]
        taken.append(name)
        if kind[0] == "own":
            continue
        plist = paramList(params)
        args = ", ".join(p.name for p in params)
        extra = f", {kind[1]}" if len(kind) > 1 else ""
        macro = "NPRGL_COMPOSITOR_" + re.sub(r"([A-Z])", r"_\1", kind[0]).upper()
        out.append(f"{macro}({ret}, {name}{extra}, ({plist}), ({args}))")
    out.append("inline void fillCompositorDispatch(GlDispatch& d)\n{")
    out += [f"    d.{name} = c_{name};" for name in taken]
    out.append("}")
    return "\n".join(out) + "\n"


def emitDecode(cmds, groups):
    """decodeCall<Visitor>: decodes one call's arguments and hands them to the visitor as
    replay(...) (typed) and dump (named, printed)."""
    # One function per command, called from a switch of returns: one big switch would hold
    # every case's locals in one frame (at -O0 and under ASan, tens of kilobytes), and a
    # display list calls back into decodeCall up to 64 deep (GL_MAX_LIST_NESTING).
    out = ["// Generated by shim/gen_codec.py. Do not edit.",
           "namespace decode {",
           "// A recorded shader or program name as the replaying sink knows it (CREATES).",
           "template <typename Sink, typename N>",
           "N objectName(Sink& sink, N recorded)",
           "{",
           "    if constexpr (requires { sink.objectName(recorded); }) {",
           "        return N(sink.objectName(recorded));",
           "    } else {",
           "        return recorded;",
           "    }",
           "}"]
    for op, (ret, name, params, mode) in enumerate(cmds):
        if mode != "record":
            continue
        variable = any(p.kind != "scalar" for p in params)
        out.append("template <typename Sink>")
        out.append(f"[[gnu::noinline]] bool {name}(CallReader& r, Sink& sink)")
        out.append("{")
        if variable:
            out.append("        CallReader::Payload payload(r);")
        for p in encodingOrder(params):
            out.append("        " + codecLine(p, 1))
        out.append("        if (!r.ok()) return false;")
        # Replay: typed call through the sink (which owns the dispatch and the substitutions).
        cargs = []
        for p in params:
            n = f"a_{p.name}"
            if p.kind == "clientptr":
                index = "a_index" if name == "glVertexAttribPointer" else "-1"
                cargs.append(f"sink.clientPointer({n}, {index})")
            elif p.kind == "sources":
                cargs.append(f"{n}.strings, {n}.lengths")
            elif p.kind == "out":
                cargs.append(f"{n}")
            elif p.kind in ("image", "indices") and p.base not in ("void", "GLvoid"):
                cargs.append(f"static_cast<const {p.base}*>({n})")
            elif p.kind == "scalar" and p.names_object and not ASSEMBLY_RE.fullmatch(name):
                cargs.append(f"objectName(sink, {n})")
            else:
                cargs.append(n)
        # glShaderSource consumes two params with one decoded value.
        if any(p.kind == "sources" for p in params):
            cargs = [c for p, c in zip(params, cargs) if p.name != "length"]
        out.append("        if constexpr (Sink::kReplays) {")
        out.append(f"            if (!sink.before({op})) return false;")
        out += checkLines(op, name, params)
        if name in ISSUED:
            call = ", ".join(cargs)
            out.append(f"            if constexpr (requires {{ sink.issue_{name}({call}); }}) {{")
            out.append(f"                sink.issue_{name}({call});")
            out.append("            } else {")
            out.append(f"                sink.gl().{name}({call});")
            out.append("            }")
        elif name in CREATES:
            out.append(f"            const auto made_ = sink.gl().{name}({', '.join(cargs)});")
            out.append("            if constexpr (requires { sink.created(made_); }) {")
            out.append("                sink.created(made_);")
            out.append("            }")
        else:
            out.append(f"            sink.gl().{name}({', '.join(cargs)});")
        out.append(f"            sink.after({op});")
        out.append("        } else {")
        out.append(f'            sink.begin("{name}");')
        for p in params:
            n = f"a_{p.name}"
            if p.kind == "scalar":
                if p.base == "GLenum":
                    gid = groups.get(p.group, 0)
                    out.append(f'            sink.argEnum("{p.name}", {n}, {gid});')
                elif p.base == "GLbitfield":
                    gid = groups.get(p.group, 0)
                    out.append(f'            sink.argBits("{p.name}", {n}, {gid});')
                else:
                    out.append(f'            sink.arg("{p.name}", {n});')
            elif p.kind == "array":
                out.append(f'            sink.argArray("{p.name}", {n}, {sub(p.count, "a_")});')
            elif p.kind in ("image", "indices", "unpacked"):
                out.append(f'            sink.argBlob("{p.name}", {n});')
            elif p.kind in ("string", "text"):
                out.append(f'            sink.argString("{p.name}", {n});')
            elif p.kind == "sources":
                out.append(f'            sink.argSources("{p.name}", {n});')
            elif p.kind == "clientptr":
                out.append(f'            sink.argPointer("{p.name}", {n});')
        out.append("            sink.end();")
        out.append("        }")
        if variable:
            out.append("        if (!payload.finish()) return false;")
        out.append("        return true;")
        out.append("}")
    out += ["} // namespace decode",
            "// Returns false (with r.error()) on malformed input.",
            "template <typename Sink>",
            "bool decodeCall(CallReader& r, uint16_t op, Sink& sink)",
            "{",
            "    switch (op) {"]
    for op, (ret, name, params, mode) in enumerate(cmds):
        if mode == "record":
            out.append(f"    case {op}: return decode::{name}(r, sink);")
    out.append("    default:")
    out.append("        return sink.pseudo(r, op);")
    out.append("    }")
    out.append("}")
    return "\n".join(out) + "\n"


def checkLines(op, name, params):
    """The replay branch's optional checks (see CHECKED)."""
    out = []

    def guarded(call):
        out.append(f"            if constexpr (requires {{ {call}; }}) {{")
        out.append(f"                if (!{call}) return false;")
        out.append("            }")

    for p in params:
        if p.kind == "image":
            guarded(f"sink.checkImage({op}, a_{p.name}_img, {sub(p.count, 'a_')})")
        elif p.kind == "unpacked":
            guarded(f"sink.checkUnpacked({op}, a_{p.name}_img, {sub(p.count, 'a_')})")
    if name in CHECKED:
        args = [f"a_{p.name}" for p in params]
        args += [f"a_{p.name}_img" for p in params
                 if p.kind in ("image", "indices", "unpacked")]
        guarded(f"sink.check_{name}({', '.join(args)})")
    return out


def emitEnums(gl, groups, bitGroups):
    """Enum names per group (group 0: any), for GL <= 2.1 features; every bit of the groups
    of GLbitfield parameters (a recorded glMapBufferRange's GL_MAP_WRITE_BIT is GL 3.0)."""
    wanted = set()
    for feature in gl.findall("feature"):
        if feature.get("api") == "gl" and gen_api.glVersion(feature) <= gen_api.GL_MAX_VERSION:
            for req in feature.findall("require"):
                for e in req.findall("enum"):
                    wanted.add(e.get("name"))
    rows = {}
    for enums in gl.findall("enums"):
        for e in enums.findall("enum"):
            name, value = e.get("name"), e.get("value")
            egroups = (e.get("group") or "").split(",")
            bits = any(g in bitGroups for g in egroups)
            if (name not in wanted and not bits) or value is None or \
                    e.get("api") not in (None, "gl"):
                continue
            try:
                v = int(value, 0)
            except ValueError:
                continue
            if v > 0xFFFFFFFF:
                continue
            if name in wanted:
                rows.setdefault((0, v), name)
            for g in egroups:
                if g in groups:
                    rows.setdefault((groups[g], v), name)
    out = ["// Generated by shim/gen_codec.py. Do not edit.",
           "struct EnumName { uint16_t group; uint32_t value; const char* name; };",
           "constexpr EnumName kEnumNames[] = {"]
    for (g, v), name in sorted(rows.items()):
        out.append(f'    {{{g}, 0x{v:X}u, "{name}"}},')
    out.append("};")
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--gl-xml", required=True)
    ap.add_argument("--out-dir", required=True)
    opts = ap.parse_args()
    gl = ET.parse(opts.gl_xml).getroot()
    elems = {}
    for c in gl.find("commands"):
        elems[gen_api.command(c)[1]] = c
    names, _ = gen_api.glCommands(gl)
    recordable = set(gen_api.requiredCommands(
        gl, lambda f: f.get("api") == "gl" and gen_api.glVersion(f) <= gen_api.GL_MAX_VERSION))
    recordable |= set(gen_api.RECORDED_EXTRA)
    cmds = []
    groups = {}
    bitGroups = set()
    for name in names:
        c = elems[name]
        ret, _ = gen_api.paramText(c.find("proto"))
        params = []
        for pe in c.findall("param"):
            ctype, pname = gen_api.paramText(pe)
            params.append(Param(ctype, pname, pe.get("len"), pe.get("group"), pe.get("class")))
            if pe.get("group") and pe.get("group") not in groups:
                groups[pe.get("group")] = len(groups) + 1
            if pe.get("group") and params[-1].base == "GLbitfield" and "*" not in ctype:
                bitGroups.add(pe.get("group"))
        mode = classify(name, params, name in recordable)
        cmds.append((ret, name, params, mode))
    files = {
        "nprgl_record.inc": emitRecord(cmds),
        "nprgl_opcodes.inc": emitOpcodes(cmds),
        "nprgl_track.inc": emitTrack(cmds),
        "nprgl_decode.inc": emitDecode(cmds, groups),
        "nprgl_enums.inc": emitEnums(gl, groups, bitGroups),
        "nprgl_compositor.inc": emitCompositor(cmds),
    }
    for fname, text in files.items():
        with open(f"{opts.out_dir}/{fname}", "w", encoding="utf-8") as f:
            f.write(text)
    modes = {}
    for c in cmds:
        modes[c[3]] = modes.get(c[3], 0) + 1
    print(f"gen_codec: {len(cmds)} commands: " +
          ", ".join(f"{n} {m}" for m, n in sorted(modes.items())), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
