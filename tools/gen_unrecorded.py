#!/usr/bin/env python3
"""gen_unrecorded.py: the entry points RayGL passes through without recording.

Every entry point of OpenGL 1.0-2.1 (the Khronos registry, gl.xml, and the
ARB/EXT names it marks as aliases of them), GLU 1.3 (GL/glu.h) and freeglut
(GL/freeglut_std.h, freeglut_ext.h) is either a row of format/commands.def
(recorded), a query (listed below: answers a question, changes nothing GL
draws), or "unrecorded": forwarded to the real function and counted per
frame (docs/design.md, "What is not recorded"). This script writes what the
unrecorded ones need, each output from the same list:

  twins      record/entry_unrecorded.c: raygl* twins that count, then call
             the real function; the id and name tables
  header     preload_unrecorded.h, force-included into the recorder's
             sources for libraygl-preload.so: each gl*, glu*, glut* name
             they call becomes a call through the pointer to the real
             function (the plain name is the counting wrapper there)
  ldscript   the exported names of libraygl-preload.so: glAccum = rayglAccum;
  dropin     include/raygl/unrecorded.h: the twins' prototypes, and the
             drop-in macros (#define glAccum rayglAccum) for raygl/gl.h
  stub       the stub GL of tests/record: each real function logs its call
  glnames    the gl* names, one a line, for tools/gen_preload.c forward

Why Python: gl.xml is XML and the GLU and freeglut prototypes are C text;
Python's standard library parses both, and meson runs on Python, so the
build needs nothing new. The C prototypes come from gl.xml and the headers
verbatim, and the compiler checks every definition against the system
headers' declarations.

Usage: gen_unrecorded.py MODE COMMANDS_DEF UNRECORDED_DEF GL_XML GL_H GLEXT_H
       GLU_H FREEGLUT_HEADER...   (freeglut_std.h, freeglut_ext.h, freeglut_ucall.h;
       output on stdout)
"""
import re
import sys
import xml.etree.ElementTree as ET

# The last GL version covered.
GL_MAX_VERSION = (2, 1)

# Queries: they return information and change neither GL's state nor the
# picture, so a trace loses nothing without them; never counted. Beside
# these names, every gl/glu/glut name starting with Get or Is is one.
QUERIES = {
    "glGetError", "glAreTexturesResident", "glAreTexturesResidentEXT",
    "glReadPixels",
    "gluErrorString", "gluCheckExtension", "gluProject", "gluUnProject",
    "gluUnProject4",
    "glutDeviceGet", "glutLayerGet", "glutGameModeGet", "glutExtensionSupported",
    "glutBitmapWidth", "glutBitmapLength", "glutBitmapHeight",
    "glutStrokeWidth", "glutStrokeLength", "glutStrokeHeight",
    "glutStrokeWidthf", "glutStrokeLengthf",
}
QUERY_PREFIXES = ("glGet", "glIs", "gluGet", "glutGet")


# GLUT's text, seen through by the preload (format/unrecorded.def marks it
# UNREC_SEEN): its libraygl twins (the drop-in header) raise the flag under
# which freeglut's own gl* calls for the text (glBitmap for bitmap text,
# line strips for stroke text) reach the raygl* twins (record/gluttext.c),
# and count the call only where that cannot be done.
GLUT_TEXT = {"glutBitmapCharacter", "glutBitmapString", "glutStrokeCharacter",
             "glutStrokeString"}


def is_query(name):
    return name in QUERIES or name.startswith(QUERY_PREFIXES)


def classification(unrecorded_def):
    """format/unrecorded.def's rows: {name: (effect, state)} in file order,
    and the effects marked UNREC_SEEN (seen through by the preload library:
    not interposed, so that the gl* calls freeglut or GLU make for them
    reach the recorder as the program's)."""
    with open(unrecorded_def, encoding="utf-8") as f:
        text = re.sub(r"/\*.*?\*/", " ", f.read(), flags=re.S)
    seen = set()
    for m in re.finditer(r"^UNREC_EFFECT\(\s*(\w+)\s*,[^,]*,\s*(\w+)\s*,", text, re.M):
        if m.group(2) == "UNREC_SEEN":
            seen.add(m.group(1))
    rows = []
    for m in re.finditer(r"^UNREC\(\s*(\w+)\s*,\s*(\w+)\s*,\s*(\w+)\s*\)", text, re.M):
        rows.append((m.group(1), m.group(2), m.group(3)))
    return rows, seen


def recorded_names(commands_def):
    """The gl/glu/glut names of commands.def's GL, GLU and GLUT rows."""
    prefix = {"GL": "gl", "GLU": "glu", "GLUT": "glut"}
    names = set()
    with open(commands_def, encoding="utf-8") as f:
        for m in re.finditer(r"^RGL_CMD\(\s*0x[0-9a-fA-F]+\s*,\s*(\w+)\s*,\s*\w+\s*,\s*(\w+)\s*,",
                             f.read(), re.M):
            if m.group(1) in prefix:
                names.add(prefix[m.group(1)] + m.group(2))
    return names


class Entry:
    def __init__(self, name, ret, params):
        self.name = name      # glAccum
        self.ret = ret        # "void", "const GLubyte *"
        self.params = params  # [(declaration text, name)]
        self.ext_only = False  # declared by glext.h only, not gl.h
        self.seen_through = False  # not interposed by the preload library
        self.state = None  # the GL state its one argument sets (unrecorded.def)


def declared(header_texts, name):
    pat = re.compile(r"\b" + re.escape(name) + r"\s*\(")
    return any(pat.search(t) for t in header_texts)


def gl_entries(gl_xml, header_texts):
    root = ET.parse(gl_xml).getroot()
    core = []
    for feat in root.findall("feature"):
        if feat.get("api") != "gl":
            continue
        major, minor = (int(x) for x in feat.get("number").split("."))
        if (major, minor) > GL_MAX_VERSION:
            continue
        for req in feat.findall("require"):
            for c in req.findall("command"):
                core.append(c.get("name"))
    core_set = set(core)
    commands = {}
    for c in root.find("commands").findall("command"):
        commands[c.find("proto/name").text] = c
    # ARB/EXT names GL 1.x-2.1 took in, by gl.xml's alias marks, when the
    # system's glext.h declares them (older programs call them).
    aliases = sorted(n for n, c in commands.items()
                     if c.find("alias") is not None and c.find("alias").get("name") in core_set
                     and n not in core_set and declared(header_texts, n))
    out = []
    for name in core + aliases:
        c = commands[name]
        proto = c.find("proto")
        ret = "".join(proto.itertext())
        ret = ret[: ret.rindex(name)].strip()
        params = []
        for p in c.findall("param"):
            params.append((" ".join("".join(p.itertext()).split()), p.find("name").text))
        e = Entry(name, ret, params)
        e.ext_only = not declared(header_texts[:1], name)
        out.append(e)
    return out


def split_params(text):
    """Splits a C parameter list at its top-level commas."""
    parts, depth, cur = [], 0, ""
    for ch in text:
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    parts.append(cur)
    return [" ".join(p.split()) for p in parts if p.strip()]


def param_name(decl):
    m = re.search(r"\(\s*\*\s*(\w+)\s*\)", decl)  # a function pointer
    if m:
        return m.group(1)
    m = re.search(r"(\w+)\s*(\[[^\]]*\])?\s*$", decl)
    return m.group(1) if m else None


def header_entries(path, api, prefix):
    """Prototypes `API ret ENTRY name ( params );` of a GLU or freeglut header."""
    with open(path, encoding="utf-8", errors="replace") as f:
        text = re.sub(r"/\*.*?\*/", " ", f.read(), flags=re.S)
    pat = re.compile(r"\b" + api + r"\s+([\w\s\*]+?)\s*\b" + r"(?:GLAPIENTRY|FGAPIENTRY)\s+(" +
                     prefix + r"[A-Z]\w*)\s*\(([^;]*)\)\s*;")
    out = []
    for m in pat.finditer(text):
        ret = " ".join(m.group(1).split())
        params = []
        plist = split_params(m.group(3))
        if plist != ["void"]:
            for k, decl in enumerate(plist):
                n = param_name(decl)
                if n is None or n in ("void", "int", "char", "double", "float", "GLenum",
                                      "GLint", "GLfloat", "GLdouble", "GLboolean", "unsigned"):
                    raise SystemExit("gen_unrecorded: %s: %s: parameter %d has no name" %
                                     (path, m.group(2), k + 1))
                params.append((decl, n))
        out.append(Entry(m.group(2), ret, params))
    return out


def fail(msg):
    raise SystemExit("gen_unrecorded.py: " + msg)


def entries(argv):
    commands_def, unrecorded_def, gl_xml, gl_h, glext_h, glu_h = argv[:6]
    texts = []
    for p in (gl_h, glext_h):
        with open(p, encoding="utf-8", errors="replace") as f:
            texts.append(f.read())
    recorded = recorded_names(commands_def)
    all_entries = gl_entries(gl_xml, texts) + header_entries(glu_h, "GLAPI", "glu")
    for h in argv[6:]:
        all_entries += header_entries(h, "FGAPI", "glut")
    rows, seen_effects = classification(unrecorded_def)
    where = "format/unrecorded.def"
    names = [r[0] for r in rows]
    for a, b in zip(names, names[1:]):
        if a.encode() >= b.encode():
            fail("%s: %s before %s: rows out of strcmp order, or a duplicate" % (where, a, b))
    row = {r[0]: r for r in rows}
    stale = sorted(n for n in row if n in recorded or is_query(n))
    if stale:
        fail("%s: %s recorded or a query now: drop the row%s" %
             (where, ", ".join(stale), "s" if len(stale) > 1 else ""))
    seen, out, missing = set(), [], []
    for e in all_entries:
        if e.name in seen or e.name in recorded or is_query(e.name):
            continue
        seen.add(e.name)
        r = row.get(e.name)
        if r is None:
            missing.append(e.name)
            continue
        e.seen_through = r[1] in seen_effects
        if r[2] != "0":
            if len(e.params) != 1 or not e.params[0][0].startswith("GLenum") or e.ret != "void":
                fail("%s: %s: a STATE column needs one GLenum argument" % (where, e.name))
            e.state = r[2]
        out.append(e)
    if missing:
        fail("%s: no row for %s (say what %s can change in the picture)" %
             (where, ", ".join(sorted(missing)), "they" if len(missing) > 1 else "it"))
    # Ids are this order: the trace stores names, so ids may change freely.
    out.sort(key=lambda e: e.name)
    return out


def twin_name(name):
    return "ray" + name


def proto(e, name):
    params = ", ".join(d for d, _ in e.params) or "void"
    ret = e.ret
    sep = "" if ret.endswith("*") else " "
    return "%s%s%s(%s)" % (ret, sep, name, params)


def call_args(e):
    return ", ".join(n for _, n in e.params)


HEAD = """/* %s: generated by tools/gen_unrecorded.py from commands.def, gl.xml, GLU
 * and freeglut's headers. Never edited by hand. */
"""


def out_twins(es):
    print(HEAD % "entry_unrecorded.c", end="")
    print("#define GL_GLEXT_PROTOTYPES 1")
    print('#include "raygl/unrecorded.h"')
    print('#include "recorder.h"')
    print('#include "unrecorded.h"')
    print()
    print("/* Each twin has the type of its real function (the system headers'). */")
    print("#define RGL_SAME_TYPE(a, b) \\")
    print("    _Static_assert(__builtin_types_compatible_p(__typeof__(&a), __typeof__(&b)), #a)")
    print()
    print("const unsigned rgl_unrecorded_total = %d;" % len(es))
    print("const char *const rgl_unrecorded_names[%d] = {" % len(es))
    for e in es:
        print('    "%s",' % e.name)
    print("};")
    for i, e in enumerate(es):
        print()
        print("RGL_EXPORT %s" % proto(e, twin_name(e.name)))
        print("{")
        if e.state:
            print("    rgl_unrecorded_count_state(%d, %s, (GLint)%s);" % (i, e.state, e.params[0][1]))
            ret = "" if e.ret == "void" else "return "
            print("    %s%s(%s);" % (ret, e.name, call_args(e)))
        elif e.name in GLUT_TEXT:
            assert e.ret == "void" and e.seen_through, e.name
            print("    int seen = rgl_glut_text_enter();")
            print("    if (!seen)")
            print("        rgl_unrecorded_count(%d);" % i)
            print("    %s(%s);" % (e.name, call_args(e)))
            print("    rgl_glut_text_leave(seen);")
        else:
            print("    rgl_unrecorded_count(%d);" % i)
            ret = "" if e.ret == "void" else "return "
            print("    %s%s(%s);" % (ret, e.name, call_args(e)))
        print("}")
        print("RGL_SAME_TYPE(%s, %s);" % (e.name, twin_name(e.name)))
    print()
    print("#ifdef RGL_PRELOAD_UNRECORDED_H")
    print("/* The preload library's lookups hand these out for the names. */")
    print("const rgl_real_fn rgl_unrecorded_twins[RGL_UNRECORDED_COUNT] = {")
    for e in es:
        print("    %s," % ("NULL /* seen through */" if e.seen_through
                           else "(rgl_real_fn)" + twin_name(e.name)))
    print("};")
    print("#endif")


def out_header(es):
    print(HEAD % "preload_unrecorded.h", end="")
    print("#ifndef RGL_PRELOAD_UNRECORDED_H")
    print("#define RGL_PRELOAD_UNRECORDED_H")
    print("#define GL_GLEXT_PROTOTYPES 1")
    print("#include <GL/gl.h>")
    print("#include <GL/glext.h>")
    print("#include <GL/glu.h>")
    print("#include <GL/freeglut.h>")
    print('#include "preload.h"')
    print("#define RGL_UNRECORDED_COUNT %d" % len(es))
    print("extern rgl_real_fn rgl_unrecorded_fns[RGL_UNRECORDED_COUNT];")
    print("extern const char *const rgl_unrecorded_names[RGL_UNRECORDED_COUNT];")
    print("extern const rgl_real_fn rgl_unrecorded_twins[RGL_UNRECORDED_COUNT];")
    print("rgl_real_fn rgl_unrecorded_resolve(unsigned index);")
    print("#define RGL_UNREC_CALL(i, name, ...) \\")
    print("    (*(__typeof__(name) *)(rgl_unrecorded_fns[i] ? rgl_unrecorded_fns[i] \\")
    print("                                                 : rgl_unrecorded_resolve(i)))(__VA_ARGS__)")
    for i, e in enumerate(es):
        print("#define %s(...) RGL_UNREC_CALL(%d, %s, __VA_ARGS__)" % (e.name, i, e.name))
    print("#endif")


def out_ldscript(es):
    print("/* preload_unrecorded.ld: generated by tools/gen_unrecorded.py: the unrecorded")
    print(" * names libraygl-preload.so interposes are its counting raygl* twins. */")
    for e in es:
        if not e.seen_through:
            print("%s = %s;" % (e.name, twin_name(e.name)))


def out_dropin(es):
    print(HEAD % "raygl/unrecorded.h", end="")
    print("""/* The raygl* twins of the calls RayGL does not record: each counts the call
 * (the trace says, per frame, which calls were not recorded and how many
 * times) and makes the real call. Included by raygl/gl.h, which then also
 * turns the gl*, glu* and glut* names into them. */
#ifndef RAYGL_UNRECORDED_H
#define RAYGL_UNRECORDED_H
#include <stdarg.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
#include <GL/freeglut_std.h>
#include <GL/freeglut_ext.h>
#include <raygl.h>
#ifdef __cplusplus
extern "C" {
#endif""")
    for e in es:
        print("RAYGL_API %s;" % proto(e, twin_name(e.name)))
    print("""#ifdef __cplusplus
}
#endif
#endif""")
    print("/* Outside the guard: raygl/gl.h asks for the macros after the prototypes. */")
    print("#if defined(RAYGL_GL_H) && !defined(RAYGL_UNRECORDED_MACROS)")
    print("#define RAYGL_UNRECORDED_MACROS")
    for e in es:
        if not e.ext_only:
            print("#define %s %s" % (e.name, twin_name(e.name)))
    print("/* Names only glext.h declares: a program without GL_GLEXT_PROTOTYPES")
    print(" * looks them up into function pointers of those very names. */")
    print("#ifdef GL_GLEXT_PROTOTYPES")
    for e in es:
        if e.ext_only:
            print("#define %s %s" % (e.name, twin_name(e.name)))
    print("#endif")
    print("#endif")


def out_stub(es):
    print(HEAD % "stub_unrecorded.c", end="")
    print("/* Weak: stubgl.c's own definitions (glReadBuffer, ...) win. */")
    print("#define GL_GLEXT_PROTOTYPES 1")
    print("#include <GL/gl.h>")
    print("#include <GL/glext.h>")
    print("#include <GL/glu.h>")
    print("#include <GL/freeglut.h>")
    print('#include "stubgl.h"')
    for e in es:
        print()
        print("__attribute__((weak)) " + proto(e, e.name))
        print("{")
        for _, n in e.params:
            print("    (void)%s;" % n)
        print('    stub_log_name("%s");' % e.name)
        if e.ret != "void":
            print("    return (%s)0;" % e.ret)
        print("}")


def out_glnames(es):
    # For tools/gen_preload.c forward: libraygl's twins reach these gl*
    # functions through the current context's table too (record/forward.h).
    for e in es:
        if e.name.startswith("gl") and not e.name.startswith(("glu", "glut")):
            print(e.name)


def main(argv):
    modes = {"twins": out_twins, "header": out_header, "ldscript": out_ldscript,
             "dropin": out_dropin, "stub": out_stub, "glnames": out_glnames}
    if len(argv) < 9 or argv[1] not in modes:
        sys.stderr.write("usage: gen_unrecorded.py twins|header|ldscript|dropin|stub|glnames COMMANDS_DEF "
                         "UNRECORDED_DEF GL_XML GL_H GLEXT_H GLU_H FREEGLUT_HEADER...\n")
        return 2
    try:
        es = entries(argv[2:])
    except (OSError, ET.ParseError) as err:
        sys.stderr.write("gen_unrecorded.py: %s\n" % err)
        return 1
    modes[argv[1]](es)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
