#!/usr/bin/env python3
"""Lists the GL features a capture's stream uses, from `nprgl dump` (for the corpus report).

Usage: scripts/corpus-features.py NPRGL CAPTURE [--frames A-B]

Prints one line: the features, comma-separated (fog, lighting, two-sided lighting, local
viewer, separate specular, flat shading, 1D/2D/3D/cube textures, texture environments by mode,
texgen, multitexture, blending by function pair, alpha test, stencil, polygon offset, polygon
mode lines/points, colour and depth masks, clip planes, the program's shaders, accumulation,
pixel and bitmap drawing, render modes, line and polygon smoothing). The frames before A are
read too (they hold the display lists and textures the later frames use).
"""

import re
import subprocess
import sys

ENABLES = {
    "GL_FOG": "fog",
    "GL_LIGHTING": "lighting",
    "GL_TEXTURE_1D": "1D texture",
    "GL_TEXTURE_2D": "2D texture",
    "GL_TEXTURE_3D": "3D texture",
    "GL_TEXTURE_CUBE_MAP": "cube map",
    "GL_TEXTURE_RECTANGLE": "rectangle texture",
    "GL_TEXTURE_GEN_S": "texgen",
    "GL_TEXTURE_GEN_T": "texgen",
    "GL_STENCIL_TEST": "stencil",
    "GL_ALPHA_TEST": "alpha test",
    "GL_POLYGON_OFFSET_FILL": "polygon offset",
    "GL_COLOR_MATERIAL": "colour material",
    "GL_LINE_SMOOTH": "line smooth",
    "GL_POLYGON_SMOOTH": "polygon smooth",
    "GL_POLYGON_STIPPLE": "polygon stipple",
    "GL_LINE_STIPPLE": "line stipple",
    "GL_CLIP_PLANE0": "clip plane",
    "GL_CLIP_PLANE1": "clip plane",
    "GL_POINT_SPRITE": "point sprites",
    "GL_MULTISAMPLE": "multisample",
    "GL_LOGIC_OP": "logic op",
    "GL_COLOR_LOGIC_OP": "logic op",
    "GL_MAP2_VERTEX_3": "evaluators",
    "GL_AUTO_NORMAL": "evaluators",
}
ENV_MODES = {0x2100: "GL_MODULATE", 0x1E01: "GL_REPLACE", 0x2101: "GL_DECAL", 0x0BE2: "GL_BLEND",
             0x0104: "GL_ADD", 0x8570: "GL_COMBINE"}
CALLS = {
    "glUseProgram": "own shaders",
    "glUseProgramObjectARB": "own shaders",
    "glBindProgramARB": "ARB programs",
    "glAccum": "accumulation",
    "glDrawPixels": "glDrawPixels",
    "glBitmap": "glBitmap",
    "glCopyTexImage2D": "copy to texture",
    "glCopyTexSubImage2D": "copy to texture",
    "glRenderMode": "render mode",
    "glActiveTexture": "multitexture",
    "glActiveTextureARB": "multitexture",
    "glBindFramebuffer": "framebuffer objects",
    "glBindFramebufferEXT": "framebuffer objects",
    "glClipPlane": "clip plane",
    "glEvalMesh2": "evaluators",
    "gluNurbsSurface": "evaluators",
}


def features(nprgl, capture, frames=None):
    last = frames.split("-")[-1] if frames else None
    cmd = [nprgl, "dump", capture] + (["--frames", f"1-{last}"] if last else [])
    text = subprocess.run(cmd, capture_output=True, text=True, errors="replace").stdout
    found = []

    def add(f):
        if f not in found:
            found.append(f)

    for line in text.splitlines():
        m = re.match(r"^(?:\d+ )?(gl[A-Za-z0-9]+)\((.*)\)", line)
        if not m:
            continue
        name, args = m.group(1), m.group(2)
        if name in ("glEnable", "glEnablei"):
            cap = re.search(r"cap=(GL_[A-Z0-9_]+)", args)
            if cap and cap.group(1) in ENABLES:
                add(ENABLES[cap.group(1)])
        elif name in CALLS:
            if name in ("glUseProgram", "glUseProgramObjectARB", "glBindProgramARB") and \
                    re.search(r"=(0|0x0)\)?$", args.split(",")[-1].strip()):
                continue
            if name.startswith("glActiveTexture") and "GL_TEXTURE0" in args and \
                    "GL_TEXTURE0" == re.sub(r".*=", "", args).strip():
                continue
            add(CALLS[name])
        elif name.startswith("glTexEnv") and "GL_TEXTURE_ENV_MODE" in args:
            value = re.sub(r".*=\[?", "", args).rstrip("])").strip()
            try:
                value = ENV_MODES.get(int(float(value)), value)
            except ValueError:
                pass
            if value.startswith("GL_"):
                add("texenv " + value[3:].lower())
        elif name == "glBlendFunc" or name == "glBlendFuncSeparate":
            pair = re.findall(r"=(GL_[A-Z_]+)", args)
            if pair[:2] and pair[:2] != ["GL_ONE", "GL_ZERO"]:
                add("blend " + "/".join(p[3:].lower() for p in pair[:2]))
        elif name == "glPolygonMode" and ("GL_LINE" in args or "GL_POINT" in args):
            add("polygon mode " + ("lines" if "GL_LINE" in args else "points"))
        elif name == "glShadeModel" and "GL_FLAT" in args:
            add("flat shading")
        elif name.startswith("glLightModel"):
            if "GL_LIGHT_MODEL_TWO_SIDE" in args and not args.rstrip(")").endswith(("0", "[0]")):
                add("two-sided lighting")
            if "GL_LIGHT_MODEL_LOCAL_VIEWER" in args and not args.rstrip(")").endswith(("0", "[0]")):
                add("local viewer")
            if "GL_SEPARATE_SPECULAR_COLOR" in args:
                add("separate specular")
        elif name == "glColorMask" and "0" in re.findall(r"=(\w+)", args)[:4] \
                or name == "glColorMask" and "GL_FALSE" in args:
            add("colour mask")
        elif name == "glDepthMask" and ("0" in args or "GL_FALSE" in args):
            add("depth writes off")
        elif name.startswith("glTexGen") and "GL_SPHERE_MAP" in args:
            add("sphere map")
        elif name.startswith("glLight") and "GL_SPOT_CUTOFF" in args:
            add("spot lights")
        elif name.startswith("glMaterial") and "GL_EMISSION" in args:
            add("emission")
        elif name.startswith("glMaterial") and "GL_SPECULAR" in args:
            add("specular")
    return found


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    frames = None
    if "--frames" in sys.argv:
        frames = sys.argv[sys.argv.index("--frames") + 1]
    print(", ".join(features(sys.argv[1], sys.argv[2], frames)))


if __name__ == "__main__":
    main()
