#!/usr/bin/env python3
"""Generates nprgl's API list from the Khronos registry.

Emits ONE list, re-included by the shim to make the exported thunks, the real-pointer table,
the name table and (later) recorder opcodes and the replay switch:

    NPRGL_GL(ret, name, (params), (args))              every GL 1.0-2.1 compatibility command
    NPRGL_WS(api, hooked, ret, name, (params), (args)) GLX / EGL / OSMesa entry points we export
    NPRGL_GL_ALIAS(ret, name, (params), (args), core)  ARB/EXT names the registry declares
                                                       equivalent to a command of the list

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
    "glXGetProcAddressARB",
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

# Suffixes of the aliases nprgl answers for: promoted ARB and EXT commands, which programs
# written before GL 1.5 (and SDL games) fetch by their extension names. Vendor aliases (NV,
# SGIS...) are left to the driver: some differ in detail from the core command.
ALIAS_SUFFIXES = ("ARB", "EXT")


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


def aliasesOf(root, names):
    """(alias, core) for every ARB/EXT command the registry declares an alias of a listed
    command, in registry order."""
    listed = set(names)
    out = []
    for c in root.find("commands"):
        alias = c.find("alias")
        name = c.find("proto").find("name").text
        if (alias is not None and alias.get("name") in listed and name not in listed
                and name.endswith(ALIAS_SUFFIXES)):
            out.append((name, alias.get("name")))
    return out


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
    glNames = requiredCommands(
        gl, lambda f: f.get("api") == "gl" and glVersion(f) <= GL_MAX_VERSION)

    glx = ET.parse(opts.glx_xml).getroot()
    glxCmds = {command(c)[1]: command(c) for c in glx.find("commands")}
    glxNames = requiredCommands(glx, lambda f: True) + GLX_EXTRA

    lines = [
        "// Generated by shim/gen_api.py from the Khronos registry. Do not edit.",
        f"// {len(glNames)} GL commands (1.0-2.1 compatibility), "
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
    for alias, core in aliasesOf(gl, glNames):
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
