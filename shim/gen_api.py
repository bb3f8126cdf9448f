#!/usr/bin/env python3
"""Generates nprgl's API list from the Khronos registry.

Emits ONE list, re-included by the shim to make the exported thunks, the real-pointer table,
the name table, the recorder opcodes and the replay switch:

    NPRGL_GL(ret, name, (params), (args))              every GL command a compatibility
                                                       program can reach (core 1.0-4.6 and the
                                                       gl/glcore extensions of gl.xml)
    NPRGL_WS(api, hooked, ret, name, (params), (args)) GLX / EGL / OSMesa entry points we export
    NPRGL_GL_ALIAS(ret, name, (params), (args), core)  names the registry declares equivalent
                                                       to a command of the list

The GL list keeps a fixed order, because its position is a command's opcode in captures:
first the GL 1.0-2.1 commands (format version 1 had exactly these), then the later commands
nprgl records (RECORDED_EXTRA), then every other command, in registry order.

`hooked` is 1 where nprgl has its own implementation (context and frame tracking) and 0 where
the thunk only forwards (exported so that a dlopen handle to nprgl still finds them).
"""
import argparse
import sys
import xml.etree.ElementTree as ET

GL_MAX_VERSION = (2, 1)

# GLX calls nprgl implements itself; the rest of GLX 1.0-1.4 is forwarded untouched.
GLX_HOOKED = {
    "glXMakeCurrent", "glXMakeContextCurrent", "glXCreateContext", "glXCreateNewContext",
    "glXCreateContextAttribsARB", "glXDestroyContext", "glXSwapBuffers", "glXGetProcAddress",
    "glXGetProcAddressARB", "glXCreateWindow", "glXDestroyWindow",
}
GLX_EXTRA = ["glXCreateContextAttribsARB", "glXGetProcAddressARB"]

# EGL and OSMesa have no registry in khronos-api; their few hooked calls are listed here.
EGL_CMDS = [
    ("EGLBoolean", "eglMakeCurrent",
     [("EGLDisplay", "dpy"), ("EGLSurface", "draw"), ("EGLSurface", "read"),
      ("EGLContext", "ctx")]),
    ("EGLBoolean", "eglSwapBuffers", [("EGLDisplay", "dpy"), ("EGLSurface", "surface")]),
    ("__eglMustCastToProperFunctionPointerType", "eglGetProcAddress",
     [("const char *", "procname")]),
    ("EGLBoolean", "eglDestroyContext", [("EGLDisplay", "dpy"), ("EGLContext", "ctx")]),
]
# (hooked, ret, name, params): the whole OSMesa API, so that a program that dlopens
# libOSMesa and is handed nprgl still finds every function.
OSMESA_CMDS = [
    (1, "GLboolean", "OSMesaMakeCurrent",
     [("OSMesaContext", "ctx"), ("void *", "buffer"), ("GLenum", "type"), ("GLsizei", "width"),
      ("GLsizei", "height")]),
    (1, "OSMESAproc", "OSMesaGetProcAddress", [("const char *", "funcName")]),
    (1, "void", "OSMesaDestroyContext", [("OSMesaContext", "ctx")]),
    (0, "OSMesaContext", "OSMesaCreateContext",
     [("GLenum", "format"), ("OSMesaContext", "sharelist")]),
    (0, "OSMesaContext", "OSMesaCreateContextExt",
     [("GLenum", "format"), ("GLint", "depthBits"), ("GLint", "stencilBits"),
      ("GLint", "accumBits"), ("OSMesaContext", "sharelist")]),
    (0, "OSMesaContext", "OSMesaCreateContextAttribs",
     [("const int *", "attribList"), ("OSMesaContext", "sharelist")]),
    (0, "OSMesaContext", "OSMesaGetCurrentContext", []),
    (0, "void", "OSMesaPixelStore", [("GLint", "pname"), ("GLint", "value")]),
    (0, "void", "OSMesaGetIntegerv", [("GLint", "pname"), ("GLint *", "value")]),
    (0, "GLboolean", "OSMesaGetDepthBuffer",
     [("OSMesaContext", "c"), ("GLint *", "width"), ("GLint *", "height"),
      ("GLint *", "bytesPerValue"), ("void **", "buffer")]),
    (0, "GLboolean", "OSMesaGetColorBuffer",
     [("OSMesaContext", "c"), ("GLint *", "width"), ("GLint *", "height"),
      ("GLint *", "format"), ("void **", "buffer")]),
    (0, "void", "OSMesaColorClamp", [("GLboolean", "enable")]),
    (0, "void", "OSMesaPostprocess",
     [("OSMesaContext", "osmesa"), ("const char *", "filter"), ("unsigned", "enable_value")]),
]

# Commands after GL 2.1 that legacy programs use and nprgl records and replays, appended to
# the opcode space in this order (append only: opcodes are stored in captures).
RECORDED_EXTRA = [
    # Framebuffer objects: ARB/GL 3.0 names (most EXT names alias them), and the two EXT
    # binds the registry keeps apart (EXT allows names that were never generated).
    "glBindFramebuffer", "glBindFramebufferEXT", "glBindRenderbuffer", "glBindRenderbufferEXT",
    "glGenFramebuffers", "glDeleteFramebuffers", "glGenRenderbuffers", "glDeleteRenderbuffers",
    "glFramebufferTexture1D", "glFramebufferTexture2D", "glFramebufferTexture3D",
    "glFramebufferTextureLayer", "glFramebufferRenderbuffer", "glRenderbufferStorage",
    "glRenderbufferStorageMultisample", "glGenerateMipmap", "glBlitFramebuffer",
    # Compiled vertex arrays (Quake-engine games lock their arrays around multi-pass draws).
    "glLockArraysEXT", "glUnlockArraysEXT",
    # ARB shader objects with no core alias (the rest alias GL 2.0 commands).
    "glDeleteObjectARB",
    # ARB vertex and fragment programs (assembly shaders of the GL 1.x era).
    "glGenProgramsARB", "glDeleteProgramsARB", "glBindProgramARB", "glProgramStringARB",
    "glProgramEnvParameter4fARB", "glProgramEnvParameter4fvARB", "glProgramEnvParameter4dARB",
    "glProgramEnvParameter4dvARB", "glProgramLocalParameter4fARB",
    "glProgramLocalParameter4fvARB", "glProgramLocalParameter4dARB",
    "glProgramLocalParameter4dvARB",
]


def paramText(elem):
    """Returns (type, name) of a <param> or <proto>."""
    name = elem.find("name").text
    text = "".join(elem.itertext()).strip()
    ctype = text[: text.rfind(name)].strip()
    return ctype, name


def command(elem):
    ret, name = paramText(elem.find("proto"))
    return ret, name, [paramText(p) for p in elem.findall("param")]


def requiredCommands(root, keep):
    """Commands required by the <feature>s for which keep(feature) is true, in registry order."""
    names = []
    for feature in root.findall("feature"):
        if not keep(feature):
            continue
        for req in feature.findall("require"):
            for cmd in req.findall("command"):
                if cmd.get("name") not in names:
                    names.append(cmd.get("name"))
    return names


def extensionCommands(root):
    """Commands of the extensions a desktop GL context can offer, in registry order."""
    names = []
    for ext in root.find("extensions"):
        if not set(ext.get("supported", "").split("|")) & {"gl", "glcore"}:
            continue
        for req in ext.findall("require"):
            if req.get("api") not in (None, "gl", "glcore"):
                continue
            for cmd in req.findall("command"):
                names.append(cmd.get("name"))
    return names


def glCommands(root):
    """(names, aliases): the GL list in opcode order and the (alias, core) pairs. A command
    with an <alias> of a listed command is not listed itself: it shares that command's slot
    (glBindBufferARB is glBindBuffer to every part of nprgl)."""
    legacy = requiredCommands(
        root, lambda f: f.get("api") == "gl" and glVersion(f) <= GL_MAX_VERSION)
    later = requiredCommands(root, lambda f: f.get("api") == "gl") + extensionCommands(root)
    aliasOf = {}
    for c in root.find("commands"):
        alias = c.find("alias")
        if alias is not None:
            aliasOf[c.find("proto").find("name").text] = alias.get("name")
    reachable = set(legacy) | set(later)
    names, seen = [], set()
    for name in legacy + RECORDED_EXTRA + later:
        if name in seen:
            continue
        seen.add(name)
        core = aliasOf.get(name)
        # Kept as its own command when it is one of the first two groups (opcodes already
        # given) or when its core command cannot be reached from desktop GL.
        if core in reachable and core != name and name not in legacy + RECORDED_EXTRA:
            continue
        names.append(name)
    listed = set(names)
    aliases = []
    for c in root.find("commands"):
        name = c.find("proto").find("name").text
        core = aliasOf.get(name)
        if name not in listed and core in listed and name in reachable:
            aliases.append((name, core))
    return names, aliases


def glVersion(feature):
    major, minor = feature.get("number").split(".")
    return int(major), int(minor)


def fmtEntry(ret, name, params):
    plist = ", ".join(f"{t} {n}" if not t.endswith("*") else f"{t}{n}" for t, n in params)
    args = ", ".join(n for _, n in params)
    return ret, name, f"({plist or 'void'})", f"({args})"


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--gl-xml", required=True)
    ap.add_argument("--glx-xml", required=True)
    ap.add_argument("-o", "--output", required=True)
    opts = ap.parse_args()

    gl = ET.parse(opts.gl_xml).getroot()
    glCmds = {command(c)[1]: command(c) for c in gl.find("commands")}
    glNames, glAliases = glCommands(gl)

    glx = ET.parse(opts.glx_xml).getroot()
    glxCmds = {command(c)[1]: command(c) for c in glx.find("commands")}
    glxNames = requiredCommands(glx, lambda f: True) + GLX_EXTRA

    lines = [
        "// Generated by shim/gen_api.py from the Khronos registry. Do not edit.",
        f"// {len(glNames)} GL commands and {len(glAliases)} aliases, "
        f"{len(glxNames) + len(EGL_CMDS) + len(OSMESA_CMDS)} window-system commands.",
        "#ifndef NPRGL_GL",
        "#define NPRGL_GL(ret, name, params, args)",
        "#endif",
        "#ifndef NPRGL_GL_ALIAS",
        "#define NPRGL_GL_ALIAS(ret, name, params, args, core)",
        "#endif",
        "#ifndef NPRGL_WS",
        "#define NPRGL_WS(api, hooked, ret, name, params, args)",
        "#endif",
    ]
    for name in glNames:
        ret, name, params, args = fmtEntry(*glCmds[name])
        lines.append(f"NPRGL_GL({ret}, {name}, {params}, {args})")
    for alias, core in glAliases:
        ret, name, params, args = fmtEntry(*glCmds[alias])
        lines.append(f"NPRGL_GL_ALIAS({ret}, {name}, {params}, {args}, {core})")
    for name in glxNames:
        ret, name, params, args = fmtEntry(*glxCmds[name])
        hooked = 1 if name in GLX_HOOKED else 0
        lines.append(f"NPRGL_WS(Glx, {hooked}, {ret}, {name}, {params}, {args})")
    for ret, name, params in EGL_CMDS:
        ret, name, params, args = fmtEntry(ret, name, params)
        lines.append(f"NPRGL_WS(Egl, 1, {ret}, {name}, {params}, {args})")
    for hooked, ret, name, params in OSMESA_CMDS:
        ret, name, params, args = fmtEntry(ret, name, params)
        lines.append(f"NPRGL_WS(OSMesa, {hooked}, {ret}, {name}, {params}, {args})")
    lines += ["#undef NPRGL_GL", "#undef NPRGL_GL_ALIAS", "#undef NPRGL_WS", ""]

    with open(opts.output, "w", encoding="utf-8") as out:
        out.write("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
