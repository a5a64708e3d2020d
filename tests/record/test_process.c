/* test_process.c: the recorder seen from outside, with the real libraygl
 * and no GL context (batch use). Each scenario runs in forked children, so
 * every one starts from a recorder that has never run:
 *
 *   crash     a child records frames and reports each frame end on a pipe;
 *             it is SIGKILLed at a random point, several times: every frame
 *             reported must be in the trace and decode cleanly
 *   failure   RAYGL_TRACE=/dev/full, a path in a missing directory, a file
 *             size limit reached mid-run, allocation failure at the Nth
 *             allocation: the program goes on, one message, earlier frames
 *             readable
 *   batch     no context: frames flagged STATE_CARRIED, RayGL's own names
 *   fork      a forked child's calls do not touch the parent's trace
 *   names     the default file name, and RAYGL_RECORD=0
 *   dropin    PROGRAM (built with -include raygl/gl.h) records
 */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "check.h"
#include "raygl.h"

static char dir[] = "/tmp/raygl-process-XXXXXX";

static void path_in_dir(char *out, size_t cap, const char *name)
{
    snprintf(out, cap, "%s/%s", dir, name);
}

/* Frame f's vertex count: frames of different sizes, some large. */
static uint32_t frame_vertices(uint32_t f) { return 500 + (f * 7919u) % 40000u; }

static void draw_frame(uint32_t f)
{
    rayglBegin(GL_TRIANGLES);
    rayglColor3f((float)f, 0, 1);
    for (uint32_t v = 0; v < frame_vertices(f); v++)
        rayglVertex3f((float)v, (float)f, 0);
    rayglEnd();
    rayglutSwapBuffers();
}

/* Checks that frame i of r is frame number i of stream 1 as draw_frame
 * made it. */
static bool frame_intact(rgl_reader *r, size_t i)
{
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, i, &fi);
    bool ok = CHECKM(c.clean, "frame %zu decodes", i);
    ok &= CHECKM(fi.number == i && fi.stream == 1, "frame %zu: number %u", i, fi.number);
    ok &= CHECKM(trace_cmds_count(&c, RGL_OP_Vertex3f) == frame_vertices((uint32_t)i),
                 "frame %zu: %zu vertices", i, trace_cmds_count(&c, RGL_OP_Vertex3f));
    ok &= CHECK(c.count > 0 && c.opcodes[c.count - 1] == RGL_OP_SwapBuffers);
    trace_cmds_free(&c);
    return ok;
}

/* ---- crash ------------------------------------------------------------------ */

static void crash_child(int fd, const char *path)
{
    if (rayglRecordOpen(path) != 0)
        _exit(3);
    for (uint32_t f = 0;; f++) {
        draw_frame(f);
        if (write(fd, &f, sizeof f) != sizeof f)
            _exit(4);
    }
}

static void test_crash(void)
{
    srand((unsigned)time(NULL) ^ (unsigned)getpid());
    for (int run = 0; run < 8; run++) {
        char path[128];
        snprintf(path, sizeof path, "%s/crash%d.raygl", dir, run);
        int p[2];
        if (!CHECK(pipe(p) == 0))
            return;
        pid_t pid = fork();
        if (pid == 0) {
            close(p[0]);
            crash_child(p[1], path);
        }
        close(p[1]);
        /* Kill after a random number of frames, at a random moment. */
        int want = 1 + rand() % 12;
        int64_t last = -1;
        uint32_t f;
        while (last + 1 < want && read(p[0], &f, sizeof f) == sizeof f)
            last = f;
        struct timespec ts = {0, (long)(rand() % 4000) * 1000};
        nanosleep(&ts, NULL);
        kill(pid, SIGKILL);
        while (read(p[0], &f, sizeof f) == sizeof f)
            last = f;
        close(p[0]);
        int status;
        waitpid(pid, &status, 0);
        CHECK(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);

        rgl_reader *r = trace_open(path);
        if (!r)
            continue;
        size_t n = rgl_reader_frame_count(r);
        CHECKM((int64_t)n >= last + 1, "run %d: %zu frames in the trace, %lld reported", run, n,
               (long long)last + 1);
        for (size_t i = 0; i < n; i++)
            frame_intact(r, i);
        rgl_reader_destroy(r);
        unlink(path);
    }
}

/* ---- failure ------------------------------------------------------------------ */

/* Runs fn in a child with stderr on a pipe; returns the child's exit status
 * and what it wrote to stderr in err. */
static int run_child(void (*fn)(const char *), const char *arg, char *err, size_t cap)
{
    int p[2];
    if (pipe(p) != 0)
        return -1;
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid == 0) {
        close(p[0]);
        dup2(p[1], STDERR_FILENO);
        int before = check_failures;
        fn(arg);
        exit(check_failures > before ? 1 : 0);
    }
    close(p[1]);
    size_t len = 0;
    ssize_t n;
    while (len + 1 < cap && (n = read(p[0], err + len, cap - 1 - len)) > 0)
        len += (size_t)n;
    err[len] = '\0';
    close(p[0]);
    int status;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/* The program goes on drawing after the failure; the status says FAILED. */
static void failing_child(const char *trace)
{
    setenv("RAYGL_TRACE", trace, 1);
    for (uint32_t f = 0; f < 40; f++)
        draw_frame(f);
    CHECK(rayglRecordStatus() == RAYGL_FAILED);
    CHECK(rayglRecordError() != NULL);
}

static size_t count_lines(const char *s)
{
    size_t n = 0;
    for (; *s; s++)
        n += *s == '\n';
    return n;
}

static void expect_one_message(const char *err, const char *want)
{
    CHECKM(count_lines(err) == 1 && strcmp(err, want) == 0, "stderr: [%s], want [%s]", err, want);
}

static void size_limited_child(const char *trace)
{
    /* A file size limit: the write that passes it fails with EFBIG. */
    struct rlimit rl = {1024 * 1024, 1024 * 1024};
    signal(SIGXFSZ, SIG_IGN);
    setrlimit(RLIMIT_FSIZE, &rl);
    failing_child(trace);
}

/* A real full disk: a 1 MiB tmpfs in a mount namespace of the child's own
 * (exit 77 where that is not allowed). The mount goes with the child, so
 * the child reads the trace back itself. */
static void tmpfs_child(const char *mnt)
{
    if (unshare(CLONE_NEWNS) != 0 || mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) != 0 ||
        mount("tmpfs", mnt, "tmpfs", 0, "size=1m") != 0)
        exit(77);
    char path[200];
    snprintf(path, sizeof path, "%s/full.raygl", mnt);
    failing_child(path);
    rgl_reader *r = trace_open(path);
    if (r) {
        size_t n = rgl_reader_frame_count(r);
        CHECKM(n >= 3, "%zu frames before the disk filled", n);
        CHECK(rgl_reader_damage_count(r) == 0);
        for (size_t i = 0; i < n; i++)
            frame_intact(r, i);
        rgl_reader_destroy(r);
    }
}

static void alloc_child(const char *nth)
{
    setenv("RAYGL_TEST_FAIL_ALLOC", nth, 1);
    setenv("RAYGL_TRACE", nth + strlen(nth) + 1, 1);
    GLuint tex;
    for (uint32_t f = 0; f < 6; f++) {
        rayglGenTextures(1, &tex);
        rayglBindTexture(GL_TEXTURE_2D, tex);
        GLubyte px[4 * 4 * 4] = {(GLubyte)f};
        rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
        GLuint l = rayglGenLists(1);
        rayglNewList(l, GL_COMPILE);
        rayglVertex2f(1, 2);
        rayglEndList();
        rayglCallList(l);
        draw_frame(f);
    }
    int st = rayglRecordStatus();
    CHECK(st == RAYGL_FAILED || st == RAYGL_RECORDING);
}

static void test_failure(void)
{
    char err[4096], path[160], want[256];

    CHECK(run_child(failing_child, "/dev/full", err, sizeof err) == 0);
    expect_one_message(err, "raygl: recording stopped: /dev/full: No space left on device\n");

    path_in_dir(path, sizeof path, "tmpfs");
    CHECK(mkdir(path, 0777) == 0);
    int rc = run_child(tmpfs_child, path, err, sizeof err);
    if (rc == 77) {
        printf("tmpfs: no mount namespace here, skipped\n");
    } else {
        CHECK(rc == 0);
        snprintf(want, sizeof want, "raygl: recording stopped: %s/full.raygl: No space left on device\n", path);
        expect_one_message(err, want);
    }
    rmdir(path);

    path_in_dir(path, sizeof path, "missing/dir/x.raygl");
    CHECK(run_child(failing_child, path, err, sizeof err) == 0);
    snprintf(want, sizeof want, "raygl: recording stopped: %s: No such file or directory\n", path);
    expect_one_message(err, want);

    path_in_dir(path, sizeof path, "limited.raygl");
    CHECK(run_child(size_limited_child, path, err, sizeof err) == 0);
    snprintf(want, sizeof want, "raygl: recording stopped: %s: File too large\n", path);
    expect_one_message(err, want);
    /* The frames before the limit are whole; the cut chunk was removed. */
    rgl_reader *r = trace_open(path);
    if (r) {
        size_t n = rgl_reader_frame_count(r);
        CHECKM(n >= 3, "%zu frames before the limit", n);
        CHECK(rgl_reader_damage_count(r) == 0);
        for (size_t i = 0; i < n; i++)
            frame_intact(r, i);
        rgl_reader_destroy(r);
    }
    unlink(path);

    /* Allocation failure at the Nth allocation, N = 1..12. */
    for (int nth = 1; nth <= 12; nth++) {
        char arg[200];
        int k = snprintf(arg, sizeof arg, "%d", nth);
        path_in_dir(arg + k + 1, sizeof arg - (size_t)k - 1, "alloc.raygl");
        CHECKM(run_child(alloc_child, arg, err, sizeof err) == 0, "alloc %d", nth);
        CHECKM(count_lines(err) == 1 &&
                   strcmp(err, "raygl: recording stopped: allocation failed: Cannot allocate memory\n") == 0,
               "alloc %d: stderr [%s]", nth, err);
        if ((r = trace_open(arg + k + 1))) {
            for (size_t i = 0; i < rgl_reader_frame_count(r); i++) {
                rgl_frame_info fi;
                trace_cmds c = trace_frame(r, i, &fi);
                CHECK(c.clean);
                trace_cmds_free(&c);
            }
            rgl_reader_destroy(r);
        }
        unlink(arg + k + 1);
    }
}

/* ---- batch -------------------------------------------------------------------- */

static void batch_child(const char *path)
{
    setenv("RAYGL_TRACE", path, 1);
    GLuint t[2];
    rayglGenTextures(2, t);
    CHECK(t[0] == 1 && t[1] == 2);
    CHECK(rayglGenLists(2) == 1);
    for (uint32_t f = 0; f < 3; f++)
        draw_frame(f);
    CHECK(rayglRecordStatus() == RAYGL_RECORDING);
    CHECK(rayglRecordPath() && strcmp(rayglRecordPath(), path) == 0);
}

static void test_batch(void)
{
    char path[160], err[1024];
    path_in_dir(path, sizeof path, "batch.raygl");
    CHECK(run_child(batch_child, path, err, sizeof err) == 0);
    CHECKM(err[0] == '\0', "stderr: %s", err);
    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) == 3);
    CHECK(rgl_reader_damage_count(r) == 0);
    for (size_t i = 0; i < rgl_reader_frame_count(r); i++) {
        rgl_frame_info fi;
        CHECK(rgl_reader_frame(r, i, &fi, NULL) == RGL_OK);
        CHECK(fi.flags == RGL_FRAME_STATE_CARRIED && fi.state == 0);
    }
    frame_intact(r, 1);
    rgl_reader_destroy(r);
    unlink(path);
}

/* ---- fork ----------------------------------------------------------------------- */

static void fork_parent(const char *path)
{
    CHECK(rayglRecordOpen(path) == 0);
    draw_frame(0);
    rayglVertex3f(1, 1, 1); /* a frame open across the fork */
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        int ok = rayglRecordStatus() == RAYGL_DISABLED;
        for (uint32_t f = 0; f < 5; f++)
            draw_frame(f);
        rayglRecordClose();
        exit(ok && rayglRecordStatus() == RAYGL_DISABLED ? 0 : 1);
    }
    int status;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    CHECK(rayglRecordStatus() == RAYGL_RECORDING);
    draw_frame(1);
    rayglRecordClose();
}

static void test_fork(void)
{
    char path[160], err[1024];
    path_in_dir(path, sizeof path, "fork.raygl");
    CHECK(run_child(fork_parent, path, err, sizeof err) == 0);
    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    /* Frame 0, then the parent's frame 1 with the vertex from before the
     * fork in front: nothing from the child, and an intact index. */
    CHECK(rgl_reader_frame_count(r) == 2);
    CHECK(rgl_reader_damage_count(r) == 0);
    frame_intact(r, 0);
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 1, &fi);
    CHECK(c.clean && fi.number == 1);
    CHECK(trace_cmds_count(&c, RGL_OP_Vertex3f) == frame_vertices(1) + 1);
    trace_cmds_free(&c);
    rgl_reader_destroy(r);
    unlink(path);
}

/* ---- names ------------------------------------------------------------------------ */

static void default_name_child(const char *sub)
{
    if (chdir(sub) != 0)
        exit(2);
    unsetenv("RAYGL_TRACE");
    draw_frame(0);
    CHECK(rayglRecordStatus() == RAYGL_RECORDING);
}

static void disabled_child(const char *sub)
{
    if (chdir(sub) != 0)
        exit(2);
    setenv("RAYGL_RECORD", "0", 1);
    unsetenv("RAYGL_TRACE");
    draw_frame(0);
    CHECK(rayglRecordStatus() == RAYGL_DISABLED);
    CHECK(rayglRecordOpen("x.raygl") == -1);
}

static void test_names(void)
{
    char sub[160], path[200], err[1024];
    path_in_dir(sub, sizeof sub, "names");
    CHECK(mkdir(sub, 0777) == 0);
    for (int k = 0; k < 3; k++)
        CHECK(run_child(default_name_child, sub, err, sizeof err) == 0);
    const char *const names[3] = {"test_process.raygl", "test_process.1.raygl",
                                  "test_process.2.raygl"};
    for (int k = 0; k < 3; k++) {
        snprintf(path, sizeof path, "%s/%s", sub, names[k]);
        rgl_reader *r = trace_open(path);
        if (r) {
            CHECK(rgl_reader_frame_count(r) == 1);
            rgl_reader_destroy(r);
        }
        unlink(path);
    }
    CHECK(run_child(disabled_child, sub, err, sizeof err) == 0);
    snprintf(path, sizeof path, "%s/test_process.raygl", sub);
    CHECK(access(path, F_OK) != 0);
    CHECK(rmdir(sub) == 0);
}

/* ---- dropin ------------------------------------------------------------------------- */

static void test_dropin(const char *program)
{
    char path[160];
    path_in_dir(path, sizeof path, "dropin.raygl");
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        setenv("RAYGL_TRACE", path, 1);
        execl(program, program, (char *)NULL);
        _exit(127);
    }
    int status;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    rgl_reader *r = trace_open(path);
    if (!r)
        return;
    CHECK(rgl_reader_frame_count(r) == 2);
    rgl_frame_info fi;
    trace_cmds c = trace_frame(r, 1, &fi);
    CHECK(trace_cmds_find(&c, 0, "glRotatef(angle=15, x=0, y=0, z=1)") >= 0);
    CHECK(trace_cmds_find(&c, 0, "glVertex3f(x=0.5, y=-0.5, z=0)") >= 0);
    CHECK(trace_cmds_find(&c, 0, "glutSolidTorus(innerRadius=0.25, outerRadius=1, sides=8, rings=16)") >= 0);
    /* The calls not recorded, counted, after the frame's last call. */
    CHECK(trace_cmds_find(&c, 0, "glutSwapBuffers()") == (long)c.count - 3);
    CHECK(trace_cmds_find(&c, 0, "@NotRecorded(name=\"glIndexf\", count=2)") == (long)c.count - 2);
    CHECK(trace_cmds_find(&c, 0, "@NotRecorded(name=\"glIndexi\", count=1)") ==
          (long)c.count - 1);
    trace_cmds_done(&c, "dropin frame 1");
    rgl_reader_destroy(r);
    unlink(path);
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return 2;
    if (!CHECK(mkdtemp(dir) != NULL))
        return check_exit();
    if (!strcmp(argv[1], "crash"))
        test_crash();
    else if (!strcmp(argv[1], "failure"))
        test_failure();
    else if (!strcmp(argv[1], "batch"))
        test_batch();
    else if (!strcmp(argv[1], "fork"))
        test_fork();
    else if (!strcmp(argv[1], "names"))
        test_names();
    else if (!strcmp(argv[1], "dropin") && argc > 2)
        test_dropin(argv[2]);
    else
        return 2;
    if (!check_failures)
        rmdir(dir);
    return check_exit();
}
