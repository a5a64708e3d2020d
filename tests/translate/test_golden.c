/* test_golden.c: the writer's output for small traces, against files.
 *
 *   test_golden GOLDEN_DIR            compare (the test)
 *   test_golden --regen GOLDEN_DIR    rewrite the files (regen-golden.sh)
 *
 * Each case builds a trace with rgl_trace_builder, translates every frame
 * to SDL and .ini text in memory and compares it byte for byte with
 * GOLDEN_DIR/<case>.pov and .ini. The files are regenerated only by
 * tests/translate/regen-golden.sh, and their diffs are reviewed like code.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frame.h"
#include "povwrite.h"
#include "scenes.h"

static int failures;

static char *read_all(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, n = 0, k;
    char *buf = malloc(cap);
    while (buf && (k = fread(buf + n, 1, cap - n, f)) > 0) {
        n += k;
        if (n == cap)
            buf = realloc(buf, cap *= 2);
    }
    fclose(f);
    *size = n;
    return buf;
}

static void compare(const char *dir, const char *name, const char *ext, const outbuf *ob,
                    int regen)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s%s", dir, name, ext);
    if (regen) {
        write_file(path, ob->buf, ob->len);
        printf("wrote %s\n", path);
        return;
    }
    size_t size = 0;
    char *want = read_all(path, &size);
    if (!want) {
        fprintf(stderr, "%s: missing (run tests/translate/regen-golden.sh)\n", path);
        failures++;
        return;
    }
    if (size != ob->len || memcmp(want, ob->buf, size) != 0) {
        size_t i = 0, line = 1;
        while (i < size && i < ob->len && want[i] == ob->buf[i])
            line += want[i++] == '\n';
        fprintf(stderr, "%s: differs from the output at line %zu (byte %zu)\n", path, line, i);
        fprintf(stderr, "--- output (%zu bytes) ---\n%.*s\n", ob->len,
                (int)(ob->len < 3000 ? ob->len : 3000), ob->buf);
        failures++;
    } else {
        printf("%s: same\n", path);
    }
    free(want);
}

static void run_case(const char *dir, const char *name, seq *frames, int nframes, int regen)
{
    trace t;
    trace_init(&t);
    for (int i = 0; i < nframes; i++)
        trace_frame(&t, 0, (uint32_t)i, 0, 0, &frames[i]);
    trace_finish(&t);
    rgl_reader *r;
    if (rgl_reader_open_memory(t.data, t.size, &r, NULL) != RGL_OK) {
        fprintf(stderr, "%s: the trace does not open\n", name);
        failures++;
        return;
    }
    translator *tr = translator_create(r, NULL);
    povwriter *pw = povwriter_create();
    outbuf ob;
    outbuf_init(&ob, 4096, NULL, NULL);
    for (int i = 0; i < nframes; i++) {
        frame_result res;
        char case_name[128], file[160];
        snprintf(case_name, sizeof case_name, nframes > 1 ? "%s-%d" : "%s", name, i);
        snprintf(file, sizeof file, "%s.pov", case_name);
        if (translator_build(tr, (size_t)i, NULL, &res) != RGL_OK) {
            fprintf(stderr, "%s: frame %d: %s\n", name, i, rgl_status_str(res.status));
            failures++;
            continue;
        }
        pov_frame_info info = {file, "golden.raygl", (uint64_t)i, 0, (uint32_t)i,
                               res.frame_name, NULL};
        ob.len = 0;
        if (povwriter_scene(pw, &ob, translator_scene(tr), &info) != 0) {
            fprintf(stderr, "%s: the writer failed\n", case_name);
            failures++;
        }
        compare(dir, case_name, ".pov", &ob, regen);
        ob.len = 0;
        char png[160];
        snprintf(png, sizeof png, "%s.png", case_name);
        pov_write_ini(&ob, translator_scene(tr), "out dir/frames", file, png);
        compare(dir, case_name, ".ini", &ob, regen);
    }
    outbuf_finish(&ob);
    povwriter_destroy(pw);
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
    for (int i = 0; i < nframes; i++)
        seq_free(&frames[i]);
}

int main(int argc, char **argv)
{
    int regen = argc == 3 && strcmp(argv[1], "--regen") == 0;
    if (argc != 2 + regen) {
        fprintf(stderr, "usage: test_golden [--regen] GOLDEN_DIR\n");
        return 2;
    }
    const char *dir = argv[1 + regen];
    seq f[2];

    seq_init(&f[0]);
    scene_paper_box(&f[0]);
    run_case(dir, "paper_box", f, 1, regen);
    seq_init(&f[0]);
    scene_smooth(&f[0]);
    run_case(dir, "smooth", f, 1, regen);
    seq_init(&f[0]);
    scene_lines_points(&f[0]);
    run_case(dir, "lines_points", f, 1, regen);
    seq_init(&f[0]);
    scene_faces(&f[0]);
    run_case(dir, "faces", f, 1, regen);
    seq_init(&f[0]);
    scene_framebegin(&f[0], "../../x\n\"}#fopen.pov");
    run_case(dir, "framebegin", f, 1, regen);
    seq_init(&f[0]);
    scene_awkward(&f[0]);
    run_case(dir, "awkward", f, 1, regen);
    if (failures) {
        fprintf(stderr, "test_golden: %d difference(s)\n", failures);
        return 1;
    }
    return 0;
}
