/* bench_translate.c: translation throughput, and POV-Ray's cost of the output.
 *
 *   bench_translate [--frames N] [--tris N] [--runs N] [--povray PATH|none] [--keep DIR]
 *                   [--no-printf] [--layout strips|triangles|strips1] [--sdl DIR]
 *   bench_translate --write-trace FILE [--frames N] [--tris N] [--layout L]
 *   bench_translate --printf-positions [--frames N] [--tris N] [--runs N]
 *
 * Builds a trace in memory with rgl_trace_builder: N frames (default 4) of
 * a lit torus (default 262144 triangles per frame, so 1M over the frames),
 * every vertex sent as glNormal3f, glColor3f, glVertex3f, in two layouts:
 * GL_TRIANGLE_STRIP rings (each vertex sent twice over the frame),
 * GL_TRIANGLES (each sent six times), and the strips again with every
 * glColor3f the same ("strips1"). For each layout it measures, on one
 * core, medians of --runs runs:
 *
 *   decode      rgl_cmd_next over the frames, nothing else
 *   translate   decode + interpret + write SDL to memory: vertices sent per
 *               second and SDL megabytes per second
 *
 * and, side by side, the raw cost of formatting the numbers the SDL holds
 * (the unique positions, normals, colours of a frame) with numfmt_f32 and
 * with snprintf("%.9g") (round-trip safe) and snprintf("%g") (not).
 *
 * With --povray (default: povray on the PATH), one frame of all the frames'
 * triangles (1M by default) is written to a file and parsed by POV-Ray
 * (64x48, no antialiasing), once with a colour per vertex and once with one
 * colour; POV-Ray's own parse time and the peak memory (/usr/bin/time -v)
 * are reported. Figures only: never pass/fail.
 *
 * With --write-trace, the layout's trace (strips unless --layout says) is
 * written to FILE and nothing is measured: bench/translate/bench_cli.sh
 * times the raygl2pov command line on it. With --printf-positions, the
 * median CPU seconds snprintf("%.9g") takes to format the positions of
 * every vertex sent in the strips trace (three numbers each) is printed:
 * the printf baseline, beside which that script puts raygl2pov.
 *
 * With --sdl DIR it only writes that frame (--frames x --tris triangles)
 * as DIR/ours-vc.pov (a colour per vertex) and DIR/ours-1c.pov (one
 * colour), with their texture images, for bench/sdl_parse.sh.
 */
#include <GL/gl.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "format.h"
#include "frame.h"
#include "povwrite.h"
#include "numfmt.h"
#include "outbuf.h"

typedef struct buf {
    uint8_t *data;
    size_t len, cap;
} buf;

static void put_cmd(buf *b, rgl_cmd *cmd)
{
    if (b->cap - b->len < 4096) {
        b->cap = b->cap ? b->cap * 2 : 1 << 20;
        b->data = realloc(b->data, b->cap);
        if (!b->data) {
            perror("bench_translate");
            exit(1);
        }
    }
    size_t n = rgl_cmd_encode(cmd, b->data + b->len, b->cap - b->len);
    if (n == 0) {
        fprintf(stderr, "bench_translate: encode failed\n");
        exit(1);
    }
    b->len += n;
}

static void cmd_f(buf *b, uint32_t op, int n, const double *v)
{
    static rgl_cmd c;
    rgl_cmd_init(&c, op);
    for (int i = 0; i < n; i++) {
        if (c.arg[i].type == RGL_T_f || c.arg[i].type == RGL_T_d)
            c.arg[i].v.f = v[i];
        else if (c.arg[i].type == RGL_T_i || c.arg[i].type == RGL_T_sz)
            c.arg[i].v.i = (int64_t)v[i];
        else
            c.arg[i].v.u = (uint64_t)v[i];
    }
    put_cmd(b, &c);
}

#define C(b, name, ...)                                                                \
    cmd_f((b), RGL_OP_##name, (int)(sizeof((double[]){__VA_ARGS__}) / sizeof(double)), \
          (double[]){__VA_ARGS__})
#define C0(b, name) cmd_f((b), RGL_OP_##name, 0, NULL)

static bool vary_colour = true;

/* A torus vertex: position, normal, colour. */
static void torus_vertex(buf *b, int i, int j, int rings, int sides, double phase)
{
    double u = 2 * M_PI * i / rings + phase, v = 2 * M_PI * j / sides;
    double nx = cos(u) * cos(v), ny = sin(u) * cos(v), nz = sin(v);
    C(b, Normal3f, nx, ny, nz);
    if (vary_colour)
        C(b, Color3f, 0.5 + 0.5 * cos(u), 0.5 + 0.5 * sin(v), 0.5 + 0.5 * cos(u + v));
    else
        C(b, Color3f, 0.8, 0.6, 0.2);
    C(b, Vertex3f, (2 + 0.7 * cos(v)) * cos(u), (2 + 0.7 * cos(v)) * sin(u), 0.7 * sin(v));
}

/* One frame: setup, then a torus of about `tris` triangles. Returns the
 * number of glVertex calls. */
static size_t build_frame(buf *b, size_t tris, int strips, double phase)
{
    int sides = 256, rings = (int)(tris / (2 * (size_t)sides));
    if (rings < 3)
        rings = 3;
    size_t verts = 0;
    C(b, Viewport, 0, 0, 640, 480);
    C(b, MatrixMode, GL_PROJECTION);
    C0(b, LoadIdentity);
    C(b, Perspective, 45, 640.0 / 480, 1, 100);
    C(b, MatrixMode, GL_MODELVIEW);
    C0(b, LoadIdentity);
    C(b, Translatef, 0, 0, -8);
    C(b, Rotatef, 30 + phase * 10, 1, 0.3, 0);
    C(b, ClearColor, 0.1, 0.1, 0.2, 1);
    C(b, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    C(b, Enable, GL_DEPTH_TEST);
    C(b, Enable, GL_LIGHTING);
    C(b, Enable, GL_LIGHT0);
    C(b, Enable, GL_COLOR_MATERIAL);
    for (int i = 0; i < rings; i++) {
        if (strips) {
            C(b, Begin, GL_TRIANGLE_STRIP);
            for (int j = 0; j <= sides; j++) {
                torus_vertex(b, i + 1, j, rings, sides, phase);
                torus_vertex(b, i, j, rings, sides, phase);
                verts += 2;
            }
            C0(b, End);
        } else {
            C(b, Begin, GL_TRIANGLES);
            for (int j = 0; j < sides; j++) {
                torus_vertex(b, i, j, rings, sides, phase);
                torus_vertex(b, i + 1, j, rings, sides, phase);
                torus_vertex(b, i + 1, j + 1, rings, sides, phase);
                torus_vertex(b, i, j, rings, sides, phase);
                torus_vertex(b, i + 1, j + 1, rings, sides, phase);
                torus_vertex(b, i, j + 1, rings, sides, phase);
                verts += 6;
            }
            C0(b, End);
        }
    }
    return verts;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

typedef struct layout_result {
    double decode_s, translate_s, sdl_bytes, verts;
} layout_result;

static bool compare_printf = true;
static const char *only_layout = NULL;

/* The layout's trace as a file, for the command-line benchmark. */
static int write_trace(const char *path, int strips, int nframes, size_t tris)
{
    rgl_trace_builder *tb = rgl_trace_builder_create();
    size_t verts = 0;
    for (int f = 0; f < nframes; f++) {
        buf b = {0};
        verts += build_frame(&b, tris, strips, 0.1 * f);
        rgl_trace_builder_frame(tb, 0, (uint32_t)f, 0, 0, b.data, b.len);
        free(b.data);
    }
    const uint8_t *data;
    size_t size;
    rgl_trace_builder_finish(tb, true, &data, &size);
    FILE *f = fopen(path, "wb");
    int rc = 0;
    if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0) {
        fprintf(stderr, "bench_translate: %s: cannot write\n", path);
        rc = 1;
    } else
        printf("%zu\n", verts);
    rgl_trace_builder_destroy(tb);
    return rc;
}

static void run_layout(const char *name, int strips, int nframes, size_t tris, int runs,
                       const char *keep)
{
    rgl_trace_builder *tb = rgl_trace_builder_create();
    size_t verts = 0, cmd_bytes = 0;
    for (int f = 0; f < nframes; f++) {
        buf b = {0};
        verts += build_frame(&b, tris, strips, 0.1 * f);
        cmd_bytes += b.len;
        rgl_trace_builder_frame(tb, 0, (uint32_t)f, 0, 0, b.data, b.len);
        free(b.data);
    }
    const uint8_t *data;
    size_t size;
    rgl_trace_builder_finish(tb, true, &data, &size);
    rgl_reader *r;
    if (rgl_reader_open_memory(data, size, &r, NULL) != RGL_OK) {
        fprintf(stderr, "bench_translate: trace does not open\n");
        exit(1);
    }
    translator *t = translator_create(r, NULL);
    povwriter *pw = povwriter_create();
    outbuf ob;
    outbuf_init(&ob, 1 << 26, NULL, NULL);

    double dec[32], tra[32], bld[32], sdl = 0;
    size_t ntri_total = 0;
    for (int k = 0; k < runs; k++) {
        /* Decoding alone. */
        double t0 = now();
        size_t ncmd = 0;
        for (size_t i = 0; i < rgl_reader_frame_count(r); i++) {
            rgl_frame_info fi;
            rgl_reader_frame(r, i, &fi, NULL);
            rgl_cmd_iter it;
            static rgl_cmd cmd;
            rgl_cmd_iter_init(&it, fi.commands, fi.commands_size, fi.commands_offset);
            while (rgl_cmd_next(&it, &cmd) == RGL_OK)
                ncmd++;
        }
        dec[k] = now() - t0;
        /* The whole translation, SDL to memory. */
        t0 = now();
        sdl = 0;
        ntri_total = 0;
        bld[k] = 0;
        for (size_t i = 0; i < rgl_reader_frame_count(r); i++) {
            frame_result res;
            double tb0 = now();
            translator_build(t, i, NULL, &res);
            bld[k] += now() - tb0;
            ntri_total += translator_scene(t)->ntris;
            pov_frame_info info = {"frame.pov", "bench.raygl", i, 0, (uint32_t)i, NULL, NULL};
            ob.len = 0;
            povwriter_scene(pw, &ob, translator_scene(t), &info);
            sdl += (double)ob.len;
        }
        tra[k] = now() - t0;
        (void)ncmd;
    }
    double d = median(dec, runs), tr = median(tra, runs), bl = median(bld, runs);
    printf("%-9s %d frames, %zu triangles, %zu vertices sent (%.1f MB of commands)\n", name,
           nframes, ntri_total, verts, cmd_bytes / 1e6);
    printf("  decode only:           %7.3f s  %6.2f M vertices/s\n", d, verts / d / 1e6);
    printf("  decode+interpret:      %7.3f s  %6.2f M vertices/s\n", bl, verts / bl / 1e6);
    printf("  decode+interpret+SDL:  %7.3f s  %6.2f M vertices/s  %7.1f MB SDL  %6.1f MB/s\n",
           tr, verts / tr / 1e6, sdl / 1e6, sdl / tr / 1e6);

    /* The numbers of one frame's SDL, formatted three ways. */
    const scene *sc = translator_scene(t);
    if (!compare_printf)
        runs = 0;
    size_t nnum = sc->nverts * 9;
    float *nums = malloc(nnum * sizeof *nums);
    for (size_t i = 0; i < sc->nverts; i++) {
        memcpy(nums + 9 * i, sc->verts[i].pos, 3 * sizeof(float));
        memcpy(nums + 9 * i + 3, sc->verts[i].normal, 3 * sizeof(float));
        memcpy(nums + 9 * i + 6, sc->verts[i].color, 3 * sizeof(float));
    }
    char *text = malloc(nnum * 32 + 64);
    double fm[32], p9[32], pg[32];
    size_t bytes_fm = 0, bytes_p9 = 0, bytes_pg = 0;
    for (int k = 0; k < runs; k++) {
        double t0 = now();
        char *p = text;
        for (size_t i = 0; i < nnum; i++) {
            p += numfmt_f32(p, nums[i]);
            *p++ = ',';
        }
        fm[k] = now() - t0;
        bytes_fm = (size_t)(p - text);
        t0 = now();
        p = text;
        for (size_t i = 0; i < nnum; i++)
            p += snprintf(p, 32, "%.9g,", (double)nums[i]);
        p9[k] = now() - t0;
        bytes_p9 = (size_t)(p - text);
        t0 = now();
        p = text;
        for (size_t i = 0; i < nnum; i++)
            p += snprintf(p, 32, "%g,", (double)nums[i]);
        pg[k] = now() - t0;
        bytes_pg = (size_t)(p - text);
    }
    double a = runs ? median(fm, runs) : 0, b9 = runs ? median(p9, runs) : 0,
           bg = runs ? median(pg, runs) : 0;
    if (runs)
    printf("  formatting %zu numbers of one frame (positions, normals, colours):\n", nnum);
    if (runs) {
        printf("    numfmt_f32 (shortest, exact): %6.1f ns/number %7.1f MB/s\n",
               a / nnum * 1e9, bytes_fm / a / 1e6);
        printf("    snprintf %%.9g (exact):        %6.1f ns/number %7.1f MB/s (%.1fx slower)\n",
               b9 / nnum * 1e9, bytes_p9 / b9 / 1e6, b9 / a);
        printf("    snprintf %%g (not exact):      %6.1f ns/number %7.1f MB/s (%.1fx slower)\n",
               bg / nnum * 1e9, bytes_pg / bg / 1e6, bg / a);
    }
    free(nums);
    free(text);

    if (keep) {
        /* The last frame of this layout as a file, for POV-Ray. */
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.pov", keep, name);
        FILE *f = fopen(path, "wb");
        if (f) {
            fwrite(ob.buf, 1, ob.len, f);
            fclose(f);
        }
    }
    outbuf_finish(&ob);
    povwriter_destroy(pw);
    translator_destroy(t);
    rgl_reader_destroy(r);
    rgl_trace_builder_destroy(tb);
}

/* One frame of `tris` triangles as SDL in dir/name (and its texture
 * images in dir/textures). Returns the triangles written, 0 on failure. */
static size_t write_frame_sdl(size_t tris, const char *dir, const char *name, bool colours,
                              double *mb)
{
    vary_colour = colours;
    rgl_trace_builder *tb = rgl_trace_builder_create();
    buf b = {0};
    build_frame(&b, tris, 1, 0);
    rgl_trace_builder_frame(tb, 0, 0, 0, 0, b.data, b.len);
    free(b.data);
    const uint8_t *data;
    size_t size;
    rgl_trace_builder_finish(tb, true, &data, &size);
    rgl_reader *r;
    rgl_reader_open_memory(data, size, &r, NULL);
    translator *t = translator_create(r, NULL);
    frame_result res;
    translator_build(t, 0, NULL, &res);
    size_t ntris = translator_scene(t)->ntris;
    outbuf ob;
    outbuf_init(&ob, 1 << 26, NULL, NULL);
    pov_frame_info info = {name, "bench.raygl", 0, 0, 0, NULL, NULL};
    povwriter *pw = povwriter_create();
    povwriter_scene(pw, &ob, translator_scene(t), &info);
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(ob.buf, 1, ob.len, f) != ob.len || fclose(f) != 0 ||
        povwriter_write_images(pw, dir, path, sizeof path) != 0) {
        perror(path);
        ntris = 0;
    }
    *mb = ob.len / 1e6;
    outbuf_finish(&ob);
    povwriter_destroy(pw);
    translator_destroy(t);
    rgl_reader_destroy(r);
    rgl_trace_builder_destroy(tb);
    vary_colour = true;
    return ntris;
}

/* One frame of `tris` triangles through POV-Ray: parse time and memory. */
static void run_povray(const char *povray, size_t tris, const char *dir, bool colours)
{
    double mb;
    size_t ntris = write_frame_sdl(tris, dir, "big.pov", colours, &mb);
    if (ntris == 0)
        return;
    char cmd[8192];
    printf("POV-Ray on one frame of %zu triangles, %s (%.1f MB of SDL, mesh2):\n", ntris,
           colours ? "a colour per vertex" : "one colour", mb);
    fflush(stdout);
    snprintf(cmd, sizeof cmd,
             "cd '%s' && /usr/bin/time -v '%s' +Ibig.pov +Obig.png +W64 +H48 -D -A "
             "File_Gamma=2.2 >pov.log 2>&1; grep -E 'Parse Time|Bounding Time|Maximum resident|User time|"
             "Elapsed' pov.log | sed 's/^[ \\t]*/  /'",
             dir, povray);
    if (system(cmd) != 0)
        printf("  (povray or /usr/bin/time failed; see %s/pov.log)\n", dir);
}

/* snprintf("%.9g") over the positions of every vertex the strips frames
 * send, alone: median CPU seconds of `runs`. */
static double printf_positions(int nframes, size_t tris, int runs)
{
    int sides = 256, rings = (int)(tris / (2 * (size_t)sides));
    if (rings < 3)
        rings = 3;
    size_t n = 0, cap = (size_t)nframes * (size_t)rings * (size_t)(sides + 1) * 6;
    float *pos = malloc(cap * sizeof *pos);
    for (int f = 0; f < nframes; f++)
        for (int i = 0; i < rings; i++)
            for (int j = 0; j <= sides; j++)
                for (int h = 1; h >= 0; h--) {
                    double u = 2 * M_PI * (i + h) / rings + 0.1 * f, v = 2 * M_PI * j / sides;
                    pos[n++] = (float)((2 + 0.7 * cos(v)) * cos(u));
                    pos[n++] = (float)((2 + 0.7 * cos(v)) * sin(u));
                    pos[n++] = (float)(0.7 * sin(v));
                }
    char text[64];
    double t[32], sink = 0;
    for (int k = 0; k < runs; k++) {
        double t0 = now();
        for (size_t i = 0; i < n; i++)
            sink += snprintf(text, sizeof text, "%.9g,", (double)pos[i]);
        t[k] = now() - t0;
    }
    free(pos);
    fprintf(stderr, "(%zu positions, %.0f bytes)\n", n / 3, sink / runs);
    return median(t, runs);
}

int main(int argc, char **argv)
{
    bool printf_only = false;
    int nframes = 4, runs = 5;
    size_t tris = 262144;
    const char *povray = "povray", *keep = NULL, *trace_out = NULL, *sdl_dir = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--frames") == 0 && i + 1 < argc)
            nframes = atoi(argv[++i]);
        else if (strcmp(argv[i], "--tris") == 0 && i + 1 < argc)
            tris = (size_t)atol(argv[++i]);
        else if (strcmp(argv[i], "--runs") == 0 && i + 1 < argc)
            runs = atoi(argv[++i]);
        else if (strcmp(argv[i], "--povray") == 0 && i + 1 < argc)
            povray = argv[++i];
        else if (strcmp(argv[i], "--keep") == 0 && i + 1 < argc)
            keep = argv[++i];
        else if (strcmp(argv[i], "--write-trace") == 0 && i + 1 < argc)
            trace_out = argv[++i];
        else if (strcmp(argv[i], "--printf-positions") == 0)
            printf_only = true;
        else if (strcmp(argv[i], "--sdl") == 0 && i + 1 < argc)
            sdl_dir = argv[++i];
        else if (strcmp(argv[i], "--no-printf") == 0)
            compare_printf = false;
        else if (strcmp(argv[i], "--layout") == 0 && i + 1 < argc)
            only_layout = argv[++i];
        else {
            fprintf(stderr, "usage: bench_translate [--frames N] [--tris N] [--runs N] "
                            "[--povray PATH|none] [--keep DIR] [--no-printf] [--layout strips|triangles|strips1] "
                            "[--write-trace FILE] [--printf-positions] [--sdl DIR]\n");
            return 2;
        }
    }
    if (printf_only) {
        printf("%.6f\n", printf_positions(nframes, tris, runs < 1 ? 1 : runs > 32 ? 32 : runs));
        return 0;
    }
    if (trace_out) {
        /* The vertex count on stdout, for the script's figures. */
        vary_colour = !only_layout || strcmp(only_layout, "strips1") != 0;
        return write_trace(trace_out, !only_layout || strcmp(only_layout, "triangles") != 0,
                           nframes, tris);
    }
    if (sdl_dir) {
        /* bench/sdl_parse.sh: the strips frame's SDL only, both colourings. */
        double mb;
        size_t tot = tris * (size_t)nframes;
        if (write_frame_sdl(tot, sdl_dir, "ours-vc.pov", true, &mb) == 0 ||
            write_frame_sdl(tot, sdl_dir, "ours-1c.pov", false, &mb) == 0)
            return 1;
        return 0;
    }
    if (runs < 1)
        runs = 1;
    if (runs > 32)
        runs = 32;
    printf("bench_translate: one core, medians of %d runs, CPU time\n", runs);
    if (!only_layout || strcmp(only_layout, "strips") == 0)
        run_layout("strips", 1, nframes, tris, runs, keep);
    if (!only_layout || strcmp(only_layout, "triangles") == 0)
        run_layout("triangles", 0, nframes, tris, runs, keep);
    if (!only_layout || strcmp(only_layout, "strips1") == 0) {
        /* The same strips, every vertex still sending glColor, all one colour. */
        vary_colour = false;
        run_layout("strips1", 1, nframes, tris, runs, keep);
        vary_colour = true;
    }
    if (strcmp(povray, "none") != 0) {
        char dir[] = "/tmp/rgl-bench-XXXXXX";
        const char *d = keep ? keep : mkdtemp(dir);
        if (d) {
            run_povray(povray, tris * (size_t)nframes, d, true);
            run_povray(povray, tris * (size_t)nframes, d, false);
            if (!keep) {
                char cmd[256];
                snprintf(cmd, sizeof cmd, "rm -rf '%s'", d);
                if (system(cmd) != 0)
                    fprintf(stderr, "bench_translate: could not remove %s\n", d);
            }
        }
    }
    return 0;
}
