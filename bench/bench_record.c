/* bench_record.c: what recording costs, measured side by side in one run.
 *
 * An immediate-mode loop (Color3f, Normal3f, Vertex3f per vertex, a few
 * matrix and light calls per frame) runs in four variants, interleaved over
 * several repetitions, and the medians are compared:
 *
 *   gl/mesa      plain gl* calls into OSMesa (software Mesa)
 *   raygl/mesa   the same calls through libraygl, recording
 *   gl/noop      plain gl* calls with no current context (GL's no-op
 *                dispatch), to isolate the recorder's own cost
 *   raygl/noop   the same through libraygl
 *
 * It prints the added nanoseconds per call, the trace bytes per call raw
 * (the frames' command bytes) and as written (the whole file), and the time
 * of the frame end (rayglutSwapBuffers: one writev of the frame). Times
 * are the thread's CPU time (user and system). With
 * apitrace installed it also runs the no-op loop under `apitrace trace` and
 * prints its cost per call, its bytes per call and the ratio to RayGL's.
 *
 *   bench_record [vertices-per-frame] [repetitions]
 *
 * Not a test: it prints figures and never fails on them.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <GL/osmesa.h>

#include "format.h"
#include "raygl.h"

#define FRAMES 2
#define MAX_REPS 31

static long vertices = 400000;
static int reps = 7;

/* Thread CPU time: on a busy machine, time spent descheduled is not the
 * recorder's. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Calls made per frame by draw_*: three per vertex plus the fixed ones. */
static double calls_per_frame(void) { return 3.0 * (double)vertices + 14; }

/* One frame's calls, the same with either prefix. */
#define DRAW_FRAME(P, frame)                                                   \
    do {                                                                       \
        static const GLfloat lpos[4] = {1, 1, 1, 0};                           \
        P##Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);                   \
        P##MatrixMode(GL_MODELVIEW);                                           \
        P##LoadIdentity();                                                     \
        P##Lightfv(GL_LIGHT0, GL_POSITION, lpos);                              \
        P##Translatef(0, 0, -2);                                               \
        P##Rotatef((float)(frame), 0, 1, 0);                                   \
        P##PushMatrix();                                                       \
        P##Scalef(0.5f, 0.5f, 0.5f);                                           \
        P##Begin(GL_TRIANGLES);                                                \
        for (long v_ = 0; v_ < vertices; v_++) {                               \
            float t_ = (float)v_ * 1e-5f;                                      \
            P##Color3f(t_, 0.5f, 1 - t_);                                      \
            P##Normal3f(0, t_, 1);                                             \
            P##Vertex3f(t_, (float)(v_ % 3), -t_);                             \
        }                                                                      \
        P##End();                                                              \
        P##PopMatrix();                                                        \
        P##Enable(GL_LIGHTING);                                                \
        P##Disable(GL_LIGHTING);                                               \
    } while (0)

/* Times FRAMES frames of plain gl* calls; returns seconds per call. */
static double run_gl(void)
{
    double t = 0;
    for (int f = 0; f < FRAMES; f++) {
        double t0 = now();
        DRAW_FRAME(gl, f);
        glFlush();
        t += now() - t0;
    }
    return t / (FRAMES * calls_per_frame());
}

typedef struct ray_result {
    double per_call;  /* seconds per call, frame ends excluded */
    double frame_end; /* seconds per rayglutSwapBuffers */
    double raw, written; /* bytes per call */
} ray_result;

static ray_result run_raygl(const char *path)
{
    ray_result r = {0, 0, 0, 0};
    if (rayglRecordOpen(path) != 0) {
        perror(path);
        exit(1);
    }
    for (int f = 0; f < FRAMES; f++) {
        double t0 = now();
        DRAW_FRAME(raygl, f);
        rayglFlush();
        double t1 = now();
        rayglutSwapBuffers();
        r.frame_end += now() - t1;
        r.per_call += t1 - t0;
    }
    rayglRecordClose();
    r.per_call /= FRAMES * calls_per_frame();
    r.frame_end /= FRAMES;

    struct stat st;
    if (stat(path, &st) == 0)
        r.written = (double)st.st_size / (FRAMES * calls_per_frame());
    rgl_reader *reader;
    if (rgl_reader_open_file(path, &reader, NULL) == RGL_OK) {
        size_t raw = 0;
        for (size_t i = 0; i < rgl_reader_frame_count(reader); i++) {
            rgl_frame_info fi;
            if (rgl_reader_frame(reader, i, &fi, NULL) == RGL_OK)
                raw += fi.commands_size;
        }
        rgl_reader_destroy(reader);
        r.raw = (double)raw / (FRAMES * calls_per_frame());
    }
    return r;
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

/* --apitrace-child: the no-op loop alone, for `apitrace trace` to wrap.
 * Prints the median seconds per call. */
static int apitrace_child(void)
{
    double t[MAX_REPS];
    for (int k = 0; k < reps; k++)
        t[k] = run_gl();
    printf("%.17g\n", median(t, reps));
    return 0;
}

/* Runs this program under apitrace; fills ns/call and bytes/call. */
static int run_apitrace(const char *self, const char *dir, double *ns, double *bytes)
{
    char trace[512], cmd[2048], vbuf[32], rbuf[32];
    snprintf(trace, sizeof trace, "%s/bench.trace", dir);
    snprintf(vbuf, sizeof vbuf, "%ld", vertices);
    snprintf(rbuf, sizeof rbuf, "%d", reps);
    snprintf(cmd, sizeof cmd, "apitrace trace --api gl -o '%s' '%s' --apitrace-child %s %s 2>/dev/null",
             trace, self, vbuf, rbuf);
    FILE *p = popen(cmd, "r");
    if (!p)
        return -1;
    double per_call = 0;
    int got = fscanf(p, "%lg", &per_call);
    if (pclose(p) != 0 || got != 1)
        return -1;
    struct stat st;
    if (stat(trace, &st) != 0)
        return -1;
    *ns = per_call * 1e9;
    *bytes = (double)st.st_size / (reps * FRAMES * calls_per_frame());
    unlink(trace);
    return 0;
}

int main(int argc, char **argv)
{
    int a = 1;
    bool child = argc > 1 && strcmp(argv[1], "--apitrace-child") == 0;
    if (child)
        a = 2;
    if (argc > a)
        vertices = atol(argv[a]);
    if (argc > a + 1)
        reps = atoi(argv[a + 1]);
    if (vertices < 1 || reps < 1 || reps > MAX_REPS) {
        fprintf(stderr, "usage: bench_record [vertices-per-frame] [repetitions <= %d]\n", MAX_REPS);
        return 2;
    }
    if (child)
        return apitrace_child();

    char dir[] = "/tmp/raygl-bench-XXXXXX";
    if (!mkdtemp(dir))
        return 1;
    char path[256];
    snprintf(path, sizeof path, "%s/bench.raygl", dir);

    /* A tiny viewport keeps Mesa's rasterisation out of the figures. */
    static unsigned char pixels[16 * 16 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!ctx) {
        fprintf(stderr, "bench_record: no OSMesa context\n");
        return 1;
    }

    double gl_mesa[MAX_REPS], ray_mesa[MAX_REPS], gl_noop[MAX_REPS], ray_noop[MAX_REPS];
    double end_mesa[MAX_REPS], raw[MAX_REPS], written[MAX_REPS];
    /* Warm-up: page in the libraries, grow the recorder's buffer. */
    OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 16, 16);
    glEnable(GL_LIGHT0);
    run_gl();
    run_raygl(path);
    for (int k = 0; k < reps; k++) {
        OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 16, 16);
        gl_mesa[k] = run_gl();
        ray_result r = run_raygl(path);
        ray_mesa[k] = r.per_call;
        end_mesa[k] = r.frame_end;
        raw[k] = r.raw;
        written[k] = r.written;
        glFinish();
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        gl_noop[k] = run_gl();
        ray_noop[k] = run_raygl(path).per_call;
    }
    double gm = median(gl_mesa, reps) * 1e9, rm = median(ray_mesa, reps) * 1e9;
    double gn = median(gl_noop, reps) * 1e9, rn = median(ray_noop, reps) * 1e9;
    double fe = median(end_mesa, reps) * 1e3;
    double frame_mb = median(raw, reps) * calls_per_frame() / 1e6;

    printf("bench_record: %ld vertices x 3 calls + 14 per frame, %d frames, %d repetitions "
           "(medians)\n", vertices, FRAMES, reps);
    printf("  with Mesa:    gl %6.2f ns/call   raygl %6.2f ns/call   added %6.2f ns/call\n", gm,
           rm, rm - gm);
    printf("  no-op GL:     gl %6.2f ns/call   raygl %6.2f ns/call   added %6.2f ns/call\n", gn,
           rn, rn - gn);
    printf("  trace bytes:  %.2f per call raw, %.2f per call as written\n", median(raw, reps),
           median(written, reps));
    printf("  frame end:    %.2f ms for a %.1f MB frame (%.2f ms/MB)\n", fe, frame_mb,
           frame_mb > 0 ? fe / frame_mb : 0);

    double an, ab;
    if (system("command -v apitrace >/dev/null 2>&1") == 0 &&
        run_apitrace(argv[0], dir, &an, &ab) == 0) {
        printf("  apitrace:     %.2f ns/call (no-op GL), added %.2f ns/call, %.2f bytes/call "
               "as written (compressed)\n", an, an - gn, ab);
        if (rn - gn > 0)
            printf("  ratio:        apitrace adds %.1fx the time RayGL adds per call\n",
                   (an - gn) / (rn - gn));
    } else {
        printf("  apitrace:     not run (not installed, or it failed)\n");
    }
    OSMesaDestroyContext(ctx);
    unlink(path);
    rmdir(dir);
    return 0;
}
