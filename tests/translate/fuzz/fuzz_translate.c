/* fuzz_translate.c: libFuzzer target for the whole translation.
 *
 * Input: a RayGL trace (it starts with the file magic), or else a bare
 * command sequence, which the target wraps into a trace: byte 0 picks the
 * frame flags and whether the same bytes also serve as the frame's state
 * snapshot, the rest are the commands, played as frame 0 and again as a
 * STATE_CARRIED frame 1. Every frame is decoded, interpreted and written
 * as SDL to memory, then the SDL is checked: printable text, balanced
 * braces and angle brackets, no nan or inf, no directive but #version,
 * #declare, #default and #ifndef ... #end (a polygon stipple's pattern
 * declared once). Each frame is also written as glTF (gltfwrite.c)
 * and the GLB checked: its header, chunk lengths and a JSON chunk of
 * printable text with balanced brackets. A failed check aborts (a crash
 * for the fuzzer).
 *
 * Built as a libFuzzer binary with -Dfuzz=true and CC=clang; the replay
 * driver (replay.c) runs it over the corpus and every kept crasher in each
 * meson test.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "format.h"
#include "frame.h"
#include "gltfwrite.h"
#include "outbuf.h"
#include "povwrite.h"

#define MAX_FRAMES 16
#define FUZZ_BUDGET_SHIFT 6

static void check(int ok, const char *what, const char *text, size_t len)
{
    if (ok)
        return;
    fprintf(stderr, "fuzz_translate: %s\n--- SDL (%zu bytes) ---\n%.*s\n", what, len,
            (int)(len < 4000 ? len : 4000), text);
    abort();
}

static int word_at(const char *p, const char *end, const char *w)
{
    size_t n = strlen(w);
    if ((size_t)(end - p) < n)
        return 0;
    for (size_t i = 0; i < n; i++) {
        char c = p[i];
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (c != w[i])
            return 0;
    }
    return 1;
}

/* The SDL invariants: see the file comment. Comments are skipped. */
static void check_sdl(const char *t, size_t len)
{
    const char *p = t, *end = t + len;
    long braces = 0, angles = 0;
    while (p < end) {
        unsigned char c = (unsigned char)*p;
        check(c == '\n' || (c >= 0x20 && c < 0x7f), "non-printable byte", t, len);
        if (c == '/' && p + 1 < end && p[1] == '/') {
            while (p < end && *p != '\n')
                p++;
            continue;
        }
        if (c == '#')
            check(word_at(p, end, "#version") || word_at(p, end, "#declare") ||
                      word_at(p, end, "#default") || word_at(p, end, "#ifndef") ||
                      word_at(p, end, "#end"),
                  "directive", t,
                  len);
        check(!word_at(p, end, "nan") && !word_at(p, end, "inf"), "nan or inf", t, len);
        braces += c == '{';
        braces -= c == '}';
        angles += c == '<';
        angles -= c == '>';
        check(braces >= 0 && angles >= 0, "unbalanced", t, len);
        p++;
    }
    check(braces == 0 && angles == 0, "unbalanced at the end", t, len);
}

static uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* The GLB invariants: see the file comment. */
static void check_glb(const char *t, size_t len)
{
    const unsigned char *b = (const unsigned char *)t;
    check(len >= 20 && memcmp(b, "glTF", 4) == 0 && le32(b + 4) == 2 && le32(b + 8) == len,
          "GLB header", t, len < 20 ? len : 20);
    uint32_t jl = le32(b + 12);
    check(jl % 4 == 0 && 20 + (size_t)jl <= len && le32(b + 16) == 0x4E4F534Au, "JSON chunk",
          t, 20);
    size_t rest = len - 20 - jl;
    check(rest == 0 || (rest >= 8 && le32(b + 20 + jl) == rest - 8 &&
                        le32(b + 24 + jl) == 0x004E4942u),
          "BIN chunk", t, 20);
    const char *j = t + 20;
    long depth = 0;
    int in_str = 0;
    for (uint32_t i = 0; i < jl; i++) {
        unsigned char c = (unsigned char)j[i];
        check(c >= 0x20 && c < 0x7f, "JSON: non-printable byte", j, jl);
        if (in_str) {
            if (c == '\\')
                i++;
            else if (c == '"')
                in_str = 0;
            continue;
        }
        in_str = c == '"';
        depth += c == '{' || c == '[';
        depth -= c == '}' || c == ']';
        check(depth >= 0, "JSON: unbalanced", j, jl);
    }
    check(depth == 0 && !in_str, "JSON: unbalanced at the end", j, jl);
}

static void translate_all(rgl_reader *r)
{
    translator *t = translator_create(r, NULL);
    povwriter *pw = povwriter_create();
    outbuf ob;
    if (!t || !pw || outbuf_init(&ob, 1 << 16, NULL, NULL) != 0) {
        povwriter_destroy(pw);
        translator_destroy(t);
        return;
    }
    /* A 1/64 budget: a list bomb is cut after a few tens of thousands of
     * vertices, so it costs the fuzzer milliseconds, not seconds, and the
     * cut paths are the same as raygl2pov's (test_bounds.sh runs those at
     * the full budget). */
    translator_set_budget_shift(t, FUZZ_BUDGET_SHIFT);
    size_t n = rgl_reader_frame_count(r);
    for (size_t i = 0; i < n && i < MAX_FRAMES; i++) {
        diag_log log;
        frame_result res;
        diag_clear(&log);
        if (translator_build(t, i, &log, &res) != RGL_OK)
            continue;
        pov_frame_info info = {"frame.pov", "fuzz.raygl", i, res.info.stream, res.info.number,
                               res.frame_name, NULL};
        ob.len = 0;
        ob.failed = false;
        if (povwriter_scene(pw, &ob, translator_scene(t), &info) == 0)
            check_sdl(ob.buf, ob.len);
        ob.len = 0;
        ob.failed = false;
        gltf_frame_info gi = {"fuzz.raygl", i, res.frame_name, NULL};
        if (gltf_write(&ob, translator_scene(t), &gi, NULL) == 0)
            check_glb(ob.buf, ob.len);
        ob.len = 0;
        if (pov_write_ini(&ob, translator_scene(t), "out dir", "frame.pov", "frame.png") == 0)
            check(memchr(ob.buf, 0, ob.len) == NULL, "NUL in ini", ob.buf, ob.len);
    }
    outbuf_finish(&ob);
    povwriter_destroy(pw);
    translator_destroy(t);
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    rgl_reader *r = NULL;
    rgl_trace_builder *b = NULL;
    const uint8_t *trace = data;
    size_t tsize = size;

    if (size < RGL_FILE_MAGIC_SIZE || memcmp(data, RGL_FILE_MAGIC, RGL_FILE_MAGIC_SIZE) != 0) {
        if (size < 1)
            return 0;
        uint32_t flags = data[0] & 3u, id = 0;
        const uint8_t *cmds = data + 1;
        size_t n = size - 1;
        static const uint8_t none[1];
        b = rgl_trace_builder_create();
        if (!b)
            return 0;
        if ((data[0] & 4u) &&
            rgl_trace_builder_resource(b, RGL_RES_COMMANDS, n ? cmds : none, n, &id) != RGL_OK)
            goto done;
        if (rgl_trace_builder_frame(b, 0, 0, flags, id, n ? cmds : none, n) != RGL_OK ||
            rgl_trace_builder_frame(b, 0, 1, RGL_FRAME_STATE_CARRIED, 0, n ? cmds : none, n) !=
                RGL_OK ||
            rgl_trace_builder_finish(b, (data[0] & 8u) == 0, &trace, &tsize) != RGL_OK)
            goto done;
    }
    if (rgl_reader_open_memory(trace, tsize, &r, NULL) == RGL_OK)
        translate_all(r);
done:
    rgl_reader_destroy(r);
    rgl_trace_builder_destroy(b);
    return 0;
}
