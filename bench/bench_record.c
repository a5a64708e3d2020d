/* bench_record.c: what recording costs in CPU time, frame writes included,
 * measured side by side in one run.
 *
 * Each measurement is a child process that runs the same immediate-mode
 * loop (Color3f, Normal3f, Vertex3f per vertex, as a real program sends
 * them, plus a few matrix and light calls) for FRAMES frames of CALLS calls:
 *
 *   gl        plain gl* calls
 *   raygl     the same calls through libraygl, recording every frame
 *             (rayglutSwapBuffers writes it), the trace closed at the end
 *   before    as raygl, with another libraygl (--before DIR: LD_LIBRARY_PATH)
 *   apitrace  the gl loop under `apitrace trace --api gl -o X`
 *
 * each with no GL context (GL's no-op dispatch, so the recorder's own cost
 * is what differs) and with an OSMesa context (16x16, so rasterisation
 * stays out of the figures). The variants run interleaved, in an order
 * that rotates each repetition, so a busy machine hurts all alike.
 *
 * A run's CPU time is user + system of the whole child process (all its
 * threads) from the start of its first frame to its exit: wait4's rusage
 * less the child's own getrusage taken just before the loop (so library
 * loading and context creation are left out, and the trace's last write,
 * close and exit are in). For apitrace the figure also holds the `apitrace`
 * launcher's own few milliseconds. The report gives medians per call, the
 * added cost over plain gl (the median of each repetition's difference to
 * its gl run), also from the second frame on (buffers grown, pages in: the
 * steady state of a long recording), the ratio to apitrace, bytes per call
 * and minor page faults per frame (a recorder that keeps its buffers takes
 * none after the first frame).
 *
 *   bench_record [--calls N] [--frames N] [--reps N] [--before LIBDIR]
 *                [--no-apitrace]
 *
 * Not a test: it prints figures and never fails on them.
 */
#include <errno.h>
#include <fcntl.h>
#include <malloc.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <GL/osmesa.h>

#include "raygl.h"

#define MAX_REPS 31
#define FIXED_CALLS 14 /* calls per frame besides the vertices' */

enum variant { V_GL, V_RAYGL, V_BEFORE, V_APITRACE, V_COUNT };
static const char *const variant_name[V_COUNT] = {"gl", "raygl", "before", "apitrace"};
enum context { C_NOOP, C_MESA, C_COUNT };
static const char *const context_name[C_COUNT] = {"noop", "mesa"};

static long vertices = 333329; /* 3 calls each: 1M calls a frame with the fixed ones */
static int frames = 8;

static double tv_sec(struct timeval tv) { return (double)tv.tv_sec + 1e-6 * (double)tv.tv_usec; }

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

/* The child: sets up the context, prints its CPU time and minor faults so
 * far, runs the frames and exits. The parent measures the rest. */
static int child(enum variant v, enum context c, const char *trace)
{
    /* glibc raises its mmap and trim thresholds when a mapped block is
     * freed, so whether Mesa's per-frame buffers are mapped and faulted in
     * anew each frame depends on what else the process freed before. Fixed
     * where glibc's own rise ends, every variant allocates alike and
     * Mesa's frames take no faults (as they settle to in a long run). */
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, 64 * 1024 * 1024);
    static unsigned char pixels[16 * 16 * 4];
    OSMesaContext ctx = NULL;
    if (c == C_MESA) {
        ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
        if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 16, 16)) {
            fprintf(stderr, "bench_record: no OSMesa context\n");
            return 1;
        }
        glEnable(GL_LIGHT0);
        /* Under apitrace, calls reach OSMesa only through TRACE_LIBGL. */
        if (!glGetString(GL_RENDERER))
            fprintf(stderr, "bench_record: the traced calls do not reach OSMesa\n");
    }
    bool rec = v == V_RAYGL || v == V_BEFORE;
    if (rec && rayglRecordOpen(trace) != 0) {
        fprintf(stderr, "bench_record: %s: %s\n", trace, strerror(errno));
        return 1;
    }
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("%.9f %.9f %ld\n", tv_sec(ru.ru_utime), tv_sec(ru.ru_stime), ru.ru_minflt);
    fflush(stdout);
    for (int f = 0; f < frames; f++) {
        if (f == 1) { /* the steady state starts: buffers grown, pages in */
            getrusage(RUSAGE_SELF, &ru);
            printf("%.9f\n", tv_sec(ru.ru_utime) + tv_sec(ru.ru_stime));
            fflush(stdout);
        }
        if (rec) {
            DRAW_FRAME(raygl, f);
            rayglFlush();
            rayglutSwapBuffers();
        } else {
            DRAW_FRAME(gl, f);
            glFlush();
        }
    }
    if (rec) {
        rayglRecordClose();
        if (rayglRecordError())
            fprintf(stderr, "bench_record: %s\n", rayglRecordError());
    }
    if (ctx) {
        glFinish();
        OSMesaDestroyContext(ctx);
    }
    return 0;
}

typedef struct result {
    double cpu;   /* seconds, first frame to exit */
    double later; /* seconds, second frame to exit */
    double sys;   /* of which system time */
    double minflt; /* minor page faults in that span */
    double bytes; /* trace file size */
} result;

/* Runs one child and measures it; returns 0 or -1. */
static int measure(const char *self, enum variant v, enum context c, const char *dir,
                   const char *before, result *out)
{
    char trace[512], cf[32], cv[32];
    snprintf(trace, sizeof trace, "%s/%s-%s.%s", dir, variant_name[v], context_name[c],
             v == V_APITRACE ? "trace" : "raygl");
    snprintf(cf, sizeof cf, "%d", frames);
    snprintf(cv, sizeof cv, "%ld", vertices);
    unlink(trace); /* its pages are freed here, not in the child */
    int fds[2];
    if (pipe(fds) != 0)
        return -1;
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        close(fds[0]);
        dup2(fds[1], STDOUT_FILENO);
        close(fds[1]);
        if (v == V_BEFORE)
            setenv("LD_LIBRARY_PATH", before, 1);
        if (v == V_APITRACE) {
            /* apitrace's own messages are not the report's. */
            int null = open("/dev/null", O_WRONLY);
            if (null >= 0)
                dup2(null, STDERR_FILENO);
            if (c == C_MESA)
                setenv("TRACE_LIBGL", "libOSMesa.so.8", 1);
            execlp("apitrace", "apitrace", "trace", "--api", "gl", "-o", trace, self,
                   "--child", variant_name[v], context_name[c], cf, cv, trace, (char *)NULL);
        } else {
            execl(self, self, "--child", variant_name[v], context_name[c], cf, cv, trace,
                  (char *)NULL);
        }
        _exit(127);
    }
    close(fds[1]);
    FILE *in = fdopen(fds[0], "r");
    double start_user = 0, start_sys = 0;
    long flt = 0;
    double second = 0;
    int got = in ? fscanf(in, "%lf %lf %ld", &start_user, &start_sys, &flt) : 0;
    if (got == 3 && frames > 1)
        got += fscanf(in, "%lf", &second);
    if (in)
        fclose(in);
    else
        close(fds[0]);
    int status;
    struct rusage ru;
    if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
        got != (frames > 1 ? 4 : 3))
        return -1;
    out->later = tv_sec(ru.ru_utime) + tv_sec(ru.ru_stime) - second;
    out->cpu = tv_sec(ru.ru_utime) + tv_sec(ru.ru_stime) - start_user - start_sys;
    out->sys = tv_sec(ru.ru_stime) - start_sys;
    out->minflt = (double)(ru.ru_minflt - flt);
    struct stat st;
    out->bytes = stat(trace, &st) == 0 ? (double)st.st_size : 0;
    unlink(trace);
    return 0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(const double *v, int n)
{
    double t[MAX_REPS];
    memcpy(t, v, (size_t)n * sizeof *t);
    qsort(t, (size_t)n, sizeof *t, cmp_double);
    return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

static int usage(void)
{
    fprintf(stderr, "usage: bench_record [--calls N] [--frames N] [--reps N <= %d] "
                    "[--before LIBDIR] [--no-apitrace]\n", MAX_REPS);
    return 2;
}

int main(int argc, char **argv)
{
    if (argc == 7 && strcmp(argv[1], "--child") == 0) {
        enum variant v = V_COUNT;
        enum context c = C_COUNT;
        for (int i = 0; i < V_COUNT; i++)
            if (strcmp(argv[2], variant_name[i]) == 0)
                v = (enum variant)i;
        for (int i = 0; i < C_COUNT; i++)
            if (strcmp(argv[3], context_name[i]) == 0)
                c = (enum context)i;
        frames = atoi(argv[4]);
        vertices = atol(argv[5]);
        if (v == V_COUNT || c == C_COUNT || frames < 1 || vertices < 1)
            return usage();
        return child(v, c, argv[6]);
    }
    int reps = 5;
    long calls = 1000000;
    const char *before = NULL;
    bool want_apitrace = true;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--no-apitrace") == 0)
            want_apitrace = false;
        else if (i + 1 < argc && strcmp(argv[i], "--calls") == 0)
            calls = atol(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--frames") == 0)
            frames = atoi(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--reps") == 0)
            reps = atoi(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--before") == 0)
            before = argv[++i];
        else
            return usage();
    }
    vertices = (calls - FIXED_CALLS) / 3;
    if (vertices < 1 || frames < 1 || reps < 1 || reps > MAX_REPS)
        return usage();
    double calls_per_frame = 3.0 * (double)vertices + FIXED_CALLS;

    char self[4096];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0)
        return 1;
    self[n] = '\0';
    char dir[] = "/tmp/raygl-bench-XXXXXX";
    if (!mkdtemp(dir)) {
        perror("bench_record: mkdtemp");
        return 1;
    }
    bool on[V_COUNT] = {true, true, before != NULL,
                        want_apitrace && system("command -v apitrace >/dev/null 2>&1") == 0};

    static result r[C_COUNT][V_COUNT][MAX_REPS];
    bool failed[C_COUNT][V_COUNT] = {{false}};
    for (int k = 0; k < reps; k++) {
        for (int c = 0; c < C_COUNT; c++) {
            for (int j = 0; j < V_COUNT; j++) {
                int v = (j + k) % V_COUNT;
                if (!on[v] || failed[c][v])
                    continue;
                if (measure(self, (enum variant)v, (enum context)c, dir, before, &r[c][v][k])) {
                    fprintf(stderr, "bench_record: the %s run with %s failed\n",
                            variant_name[v], context_name[c]);
                    failed[c][v] = true;
                }
            }
        }
    }
    rmdir(dir);

    printf("bench_record: %.0f calls a frame (%ld x Color3f, Normal3f, Vertex3f + %d), "
           "%d frames, %d repetitions, medians of CPU time (user + system, whole process, "
           "first frame to exit)\n", calls_per_frame, vertices, FIXED_CALLS, frames, reps);
    for (int c = 0; c < C_COUNT; c++) {
        printf("  %s:\n", c == C_NOOP ? "no GL context (no-op dispatch)" : "OSMesa context");
        double added[V_COUNT] = {0};
        for (int v = 0; v < V_COUNT; v++) {
            if (!on[v] || failed[c][v])
                continue;
            double cpu[MAX_REPS], sys[MAX_REPS], flt[MAX_REPS], bytes[MAX_REPS];
            for (int k = 0; k < reps; k++) {
                cpu[k] = r[c][v][k].cpu;
                sys[k] = r[c][v][k].sys;
                flt[k] = r[c][v][k].minflt;
                bytes[k] = r[c][v][k].bytes;
            }
            double total = frames * calls_per_frame;
            double ns = median(cpu, reps) / total * 1e9;
            /* Added: the median of each repetition's difference to the gl
             * run next to it in time, which a machine whose load drifts
             * hurts less than a difference of medians. */
            double diff[MAX_REPS], later[MAX_REPS];
            for (int k = 0; k < reps; k++) {
                diff[k] = r[c][v][k].cpu - r[c][V_GL][k].cpu;
                later[k] = r[c][v][k].later - r[c][V_GL][k].later;
            }
            bool paired = on[V_GL] && !failed[c][V_GL];
            added[v] = paired ? median(diff, reps) / total * 1e9 : 0;
            double added_later = paired && frames > 1
                                     ? median(later, reps) / ((frames - 1) * calls_per_frame) * 1e9
                                     : 0;
            printf("    %-9s %7.2f ns/call (system %6.2f)", variant_name[v], ns,
                   median(sys, reps) / total * 1e9);
            if (v != V_GL)
                printf("  added %7.2f (frames 2-%d: %7.2f)  %5.2f bytes/call", added[v], frames,
                       added_later, median(bytes, reps) / total);
            else
                printf("  %*s", 50, "");
            printf("  %6.0f faults/frame\n", median(flt, reps) / frames);
        }
        if (on[V_APITRACE] && !failed[c][V_APITRACE] && added[V_RAYGL] > 0)
            printf("    apitrace adds %.1fx the CPU time raygl adds\n",
                   added[V_APITRACE] / added[V_RAYGL]);
        if (on[V_BEFORE] && !failed[c][V_BEFORE] && added[V_RAYGL] > 0)
            printf("    before adds %.2fx the CPU time raygl adds\n",
                   added[V_BEFORE] / added[V_RAYGL]);
    }
    return 0;
}
