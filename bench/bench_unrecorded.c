/* bench_unrecorded.c: what counting an unrecorded call costs.
 *
 * With no current context (GL's no-op dispatch, so GL itself costs the
 * same in each), the same loop of glRasterPos2i runs in three variants,
 * interleaved over several repetitions, and the medians are compared:
 *
 *   gl       plain glRasterPos2i
 *   counted  rayglRasterPos2i: counted in the thread's stream, forwarded
 *   recorded rayglVertex2i, a recorded call of the same shape, for scale
 *
 *   bench_unrecorded [calls] [repetitions]
 *
 * Times are the thread's CPU time. Not a test: it prints figures and never
 * fails on them.
 */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#include "raygl.h"
#include "raygl/unrecorded.h"

#define MAX_REPS 31

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return v[n / 2];
}

int main(int argc, char **argv)
{
    long calls = argc > 1 ? atol(argv[1]) : 20000000;
    int reps = argc > 2 ? atoi(argv[2]) : 7;
    if (calls < 1 || reps < 1 || reps > MAX_REPS) {
        fprintf(stderr, "usage: bench_unrecorded [calls] [repetitions <= %d]\n", MAX_REPS);
        return 2;
    }
    char path[] = "/tmp/bench-unrecorded-XXXXXX";
    int fd = mkstemp(path);
    if (fd < 0 || rayglRecordOpen(path) != 0) {
        perror(path);
        return 1;
    }
    double t_gl[MAX_REPS], t_count[MAX_REPS], t_rec[MAX_REPS];
    for (int r = 0; r < reps; r++) {
        double t0 = now();
        for (long i = 0; i < calls; i++)
            glRasterPos2i((GLint)i, 1);
        double t1 = now();
        for (long i = 0; i < calls; i++)
            rayglRasterPos2i((GLint)i, 1);
        double t2 = now();
        for (long i = 0; i < calls; i++) {
            rayglVertex2i((GLint)i, 1);
            if ((i & 0xfffff) == 0xfffff)
                rayglFrameEnd(); /* keeps the frame under a chunk's size */
        }
        double t3 = now();
        rayglFrameEnd();
        t_gl[r] = t1 - t0;
        t_count[r] = t2 - t1;
        t_rec[r] = t3 - t2;
    }
    rayglRecordClose();
    close(fd);
    unlink(path);
    double gl = median(t_gl, reps) * 1e9 / (double)calls;
    double cnt = median(t_count, reps) * 1e9 / (double)calls;
    double rec = median(t_rec, reps) * 1e9 / (double)calls;
    printf("%ld calls x %d repetitions, no context (GL's no-op dispatch), medians:\n", calls, reps);
    printf("  glRasterPos2i           %6.2f ns/call\n", gl);
    printf("  rayglRasterPos2i        %6.2f ns/call (counted: +%.2f ns)\n", cnt, cnt - gl);
    printf("  rayglVertex2i (recorded) %5.2f ns/call\n", rec);
    return 0;
}
