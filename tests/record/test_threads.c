/* test_threads.c: two threads, each with its own OSMesa context, record
 * at the same time into one trace: two streams, every frame intact, frame
 * numbers in order within each stream. A third thread exits with its frame
 * still open: the thread-exit handler writes it. */
#include <pthread.h>
#include <stdatomic.h>
#include <time.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <GL/osmesa.h>

#include "check.h"
#include "raygl.h"

#define FRAMES 25

typedef struct worker {
    int index;
    bool ok;
    unsigned char pixels[32 * 32 * 4];
} worker;

static uint32_t vertices(int index, uint32_t f) { return 2000 + (uint32_t)index * 977 + f * 131; }

static void *run(void *arg)
{
    worker *w = arg;
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, w->pixels, GL_UNSIGNED_BYTE, 32, 32))
        return NULL;
    for (uint32_t f = 0; f < FRAMES; f++) {
        rayglClear(GL_COLOR_BUFFER_BIT);
        rayglLoadIdentity();
        rayglTranslatef((float)w->index, 0, 0);
        rayglBegin(GL_POINTS);
        for (uint32_t v = 0; v < vertices(w->index, f); v++)
            rayglVertex3f((float)w->index, (float)f, (float)v);
        rayglEnd();
        rayglutSwapBuffers();
    }
    glFinish();
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    w->ok = true;
    return NULL;
}

static void *run_unfinished(void *arg)
{
    (void)arg;
    rayglColor3f(1, 2, 3);
    rayglVertex3f(4, 5, 6);
    return NULL; /* no swap: the frame is written at thread exit */
}

static atomic_bool stop;

/* Records frames until told to stop, across the trace's close. */
static void *run_until_stopped(void *arg)
{
    (void)arg;
    for (uint32_t f = 0; !atomic_load(&stop); f++) {
        rayglBegin(GL_POINTS);
        for (uint32_t v = 0; v < 5000; v++)
            rayglVertex3f(7, (float)f, (float)v);
        rayglEnd();
        rayglutSwapBuffers();
    }
    return NULL;
}

/* The trace closes while another thread records: what that thread had
 * recorded of its frame is written, the rest goes nowhere, and nothing
 * breaks. */
static void test_close_while_recording(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    pthread_t th;
    CHECK(pthread_create(&th, NULL, run_until_stopped, NULL) == 0);
    struct timespec ts = {0, 50 * 1000 * 1000};
    nanosleep(&ts, NULL);
    rayglRecordClose();
    nanosleep(&ts, NULL);
    atomic_store(&stop, true);
    pthread_join(th, NULL);
    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    size_t n = rgl_reader_frame_count(r);
    CHECKM(n >= 1, "%zu frames", n);
    for (size_t i = 0; i < n; i++) {
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, i, &fi);
        CHECK(c.clean && fi.number == i);
        /* Whole frames, but for the last which may be cut at a command. */
        if (i + 1 < n)
            CHECK(trace_cmds_count(&c, RGL_OP_Vertex3f) == 5000);
        trace_cmds_free(&c);
    }
    rgl_reader_destroy(r);
}

/* Checks every vertex of the frame belongs to stream's worker and frame. */
static void check_frame(const rgl_frame_info *fi, int index)
{
    rgl_cmd_iter it;
    static rgl_cmd cmd;
    size_t n = 0;
    bool values_ok = true;
    rgl_cmd_iter_init(&it, fi->commands, fi->commands_size, fi->commands_offset);
    rgl_status st;
    while ((st = rgl_cmd_next(&it, &cmd)) == RGL_OK) {
        if (cmd.opcode != RGL_OP_Vertex3f)
            continue;
        values_ok &= rgl_arg_f(&cmd.arg[0], 0) == index &&
                     rgl_arg_f(&cmd.arg[1], 0) == fi->number &&
                     rgl_arg_f(&cmd.arg[2], 0) == (double)n;
        n++;
    }
    CHECK(st == RGL_END);
    CHECKM(values_ok && n == vertices(index, fi->number), "stream %u frame %u: %zu vertices",
           fi->stream, fi->number, n);
}

int main(void)
{
    char dir[] = "/tmp/raygl-threads-XXXXXX";
    if (!CHECK(mkdtemp(dir) != NULL))
        return check_exit();
    char path[128];
    snprintf(path, sizeof path, "%s/threads.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);

    static worker w[2];
    pthread_t th[2], extra;
    for (int k = 0; k < 2; k++) {
        w[k].index = k + 1;
        CHECK(pthread_create(&th[k], NULL, run, &w[k]) == 0);
    }
    for (int k = 0; k < 2; k++) {
        pthread_join(th[k], NULL);
        CHECK(w[k].ok);
    }
    CHECK(pthread_create(&extra, NULL, run_unfinished, NULL) == 0);
    pthread_join(extra, NULL);
    rayglRecordClose();

    rgl_reader *r = trace_open(path);
    if (!r)
        return check_exit();
    size_t n = rgl_reader_frame_count(r);
    CHECK(n == 2 * FRAMES + 1);
    CHECK(rgl_reader_damage_count(r) == 0);
    /* Streams are numbered in the order threads first record; map each to
     * its worker by the first frame's vertices. */
    uint32_t next_number[4] = {0, 0, 0, 0};
    int worker_of[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < n; i++) {
        rgl_frame_info fi;
        if (!CHECK(rgl_reader_frame(r, i, &fi, NULL) == RGL_OK))
            continue;
        if (!CHECK(fi.stream >= 1 && fi.stream <= 3))
            continue;
        CHECKM(fi.number == next_number[fi.stream], "stream %u: frame %u after %u", fi.stream,
               fi.number, next_number[fi.stream]);
        next_number[fi.stream] = fi.number + 1;
        if (fi.stream == 3) {
            trace_cmds c = trace_cmds_decode(fi.commands, fi.commands_size, fi.commands_offset);
            CHECK(c.count == 2 && trace_cmds_find(&c, 0, "glVertex3f(x=4, y=5, z=6)") == 1);
            CHECK(fi.flags == RGL_FRAME_STATE_CARRIED);
            trace_cmds_free(&c);
            continue;
        }
        CHECK(fi.flags == RGL_FRAME_LIVE_CONTEXT && fi.state != 0);
        if (!worker_of[fi.stream]) {
            rgl_cmd_iter it;
            static rgl_cmd cmd;
            rgl_cmd_iter_init(&it, fi.commands, fi.commands_size, fi.commands_offset);
            while (rgl_cmd_next(&it, &cmd) == RGL_OK)
                if (cmd.opcode == RGL_OP_Vertex3f) {
                    worker_of[fi.stream] = (int)rgl_arg_f(&cmd.arg[0], 0);
                    break;
                }
        }
        check_frame(&fi, worker_of[fi.stream]);
    }
    CHECK(next_number[1] == FRAMES && next_number[2] == FRAMES && next_number[3] == 1);
    CHECK(worker_of[1] + worker_of[2] == 3 && worker_of[1] != worker_of[2]);
    rgl_reader_destroy(r);
    unlink(path);
    test_close_while_recording(path);
    if (!check_failures) {
        unlink(path);
        rmdir(dir);
    }
    return check_exit();
}
