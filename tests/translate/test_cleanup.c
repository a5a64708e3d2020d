/* test_cleanup.c: the stop-signal cleanup (translate/proc/cleanup.h) is not cut
 * short, by the process's own exit or by the tool that started it.
 *
 * Each case runs in a forked process that stands for one of the tools:
 *
 *   exit during a stop  the tool registers a file and a child, then stops
 *       itself with SIGINT. The child holds the waiter inside its stop: told
 *       by the waiter's SIGTERM, it says so and stays until the tool is gone
 *       (at most 1 s). The tool's main thread then exits, as raygl2pov's
 *       returns from main when the waiter reaps its povray first and its
 *       waitpid finds no child. The exit must wait for the stop: the tool
 *       ends by SIGINT and the file is gone. (It used to exit 0 at once,
 *       the file left.)
 *   plain exit          no stop: the exit status is kept, also when the
 *       exiting thread holds the registry's lock.
 *   nested tools        as raygl-compare runs raygl2pov: an outer tool
 *       registers an inner one (this program again, "inner") with
 *       cleanup_tool; the inner registers a file and two children that
 *       ignore SIGTERM. SIGINT to the outer: the inner kills its children
 *       after its 10 s, removes its file and ends; the outer must give it
 *       that time. (It used to wait 10 s too, while the inner waited 10 s
 *       for each child in turn: the inner was killed, its file left.)
 *       About 10 s.
 *   a stop pending      the tool holds the registry's lock when SIGINT
 *       comes (as raygl-render does while it acts on a povray the Ctrl-C
 *       to the group ended), then calls cleanup_check, or exits. Either
 *       must make the stop, the lock still held: the tool ends by SIGINT,
 *       the file gone, the stop's words said. (The waiter used to take the
 *       signal without the lock: the check could find nothing pending and
 *       the tool go on, or exit 0.)
 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "check.h"
#include "cleanup.h"

/* The child: waits for SIGTERM (still blocked, as cleanup_start left it),
 * writes a byte to told, then stays until alive reads EOF or 1 s. */
static void held_child(int told, int alive)
{
    sigset_t term;
    sigemptyset(&term);
    sigaddset(&term, SIGTERM);
    struct timespec ten = {10, 0};
    if (sigtimedwait(&term, NULL, &ten) != SIGTERM)
        _exit(2);
    if (write(told, "t", 1) != 1)
        _exit(2);
    struct pollfd p = {alive, POLLIN, 0};
    while (poll(&p, 1, 1000) < 0 && errno == EINTR)
        ;
    _exit(0);
}

/* The tools: exit status 3 when they could not set their case up. */
static void exit_during_stop(const char *file, int unused)
{
    (void)unused;
    if (cleanup_start() != 0)
        exit(3);
    int told[2], alive[2];
    if (pipe(told) != 0 || pipe(alive) != 0)
        exit(3);
    cleanup_lock();
    long fid = cleanup_file(file);
    FILE *f = fid >= 0 ? fopen(file, "w") : NULL;
    if (!f || fclose(f) != 0)
        exit(3);
    pid_t pid = fork();
    if (pid == 0) {
        close(told[0]);
        close(alive[1]);
        held_child(told[1], alive[0]);
    }
    if (pid < 0 || cleanup_child(pid) < 0)
        exit(3);
    cleanup_unlock();
    close(told[1]);
    close(alive[0]);
    kill(getpid(), SIGINT);
    char b;
    ssize_t r;
    while ((r = read(told[0], &b, 1)) < 0 && errno == EINTR)
        ;
    if (r != 1)
        exit(3);
    /* The waiter holds the lock and waits for the child. */
    exit(0);
}

/* Exits 7, the lock held when locked. */
static void plain_exit(const char *file, int locked)
{
    if (cleanup_start() != 0)
        exit(3);
    cleanup_lock();
    long id = cleanup_file(file);
    FILE *f = id >= 0 ? fopen(file, "w") : NULL;
    if (!f || fclose(f) != 0)
        exit(3);
    cleanup_drop(id);
    if (!locked)
        cleanup_unlock();
    exit(7);
}

/* The inner tool: the file and two children that ignore SIGTERM (blocked,
 * as cleanup_start left it) registered, a byte to fd ready, then waits
 * for the stop. */
static int inner(const char *file, int ready)
{
    if (cleanup_start() != 0)
        return 3;
    cleanup_lock();
    long id = cleanup_file(file);
    FILE *f = id >= 0 ? fopen(file, "w") : NULL;
    if (!f || fclose(f) != 0)
        return 3;
    for (int k = 0; k < 2; k++) {
        pid_t pid = fork();
        if (pid == 0) {
            /* Not holding the test's output open, should it outlive us. */
            int null = open("/dev/null", O_WRONLY);
            dup2(null, 1);
            dup2(null, 2);
            sleep(60);
            _exit(0);
        }
        if (pid < 0 || cleanup_child(pid) < 0)
            return 3;
    }
    cleanup_unlock();
    if (write(ready, "r", 1) != 1)
        return 3;
    for (;;)
        pause();
}

static const char *said_path;

static void say_stop(int sig)
{
    int fd = open(said_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        if (sig == SIGINT && write(fd, "s", 1) != 1)
            _exit(3);
        close(fd);
    }
}

/* SIGINT while the lock is held; then cleanup_check (check) or exit. The
 * pause lets the waiter wake and reach the lock first. */
static void stop_pending(const char *file, int check)
{
    if (cleanup_start() != 0)
        exit(3);
    cleanup_on_stop(say_stop);
    cleanup_lock();
    long id = cleanup_file(file);
    FILE *f = id >= 0 ? fopen(file, "w") : NULL;
    if (!f || fclose(f) != 0)
        exit(3);
    kill(getpid(), SIGINT);
    struct timespec t = {0, 200 * 1000 * 1000};
    while (nanosleep(&t, &t) != 0 && errno == EINTR)
        ;
    if (check) {
        cleanup_check();
        exit(5);
    }
    exit(0);
}

static const char *self;

/* The outer tool: starts the inner as raygl-compare starts raygl2pov, then
 * stops itself once the inner is ready. */
static void nested(const char *file, int unused)
{
    (void)unused;
    int ready[2];
    if (cleanup_start() != 0 || pipe(ready) != 0)
        exit(3);
    char fd[16];
    snprintf(fd, sizeof fd, "%d", ready[1]);
    cleanup_lock();
    pid_t pid = fork();
    long id = pid > 0 ? cleanup_tool(pid) : -1;
    cleanup_unlock();
    if (pid == 0) {
        cleanup_child_signals();
        close(ready[0]);
        execl(self, self, "inner", file, fd, (char *)NULL);
        _exit(3);
    }
    if (id < 0)
        exit(3);
    close(ready[1]);
    char b;
    ssize_t r;
    while ((r = read(ready[0], &b, 1)) < 0 && errno == EINTR)
        ;
    if (r != 1)
        exit(3);
    kill(getpid(), SIGINT);
    for (;;)
        pause();
}

/* Runs fn(file, arg) in a forked process; its wait status. */
static int run(void (*fn)(const char *, int), const char *file, int arg)
{
    pid_t pid = fork();
    if (pid == 0)
        fn(file, arg);
    int st = -1;
    while (pid > 0 && waitpid(pid, &st, 0) < 0 && errno == EINTR)
        ;
    return st;
}

int main(int argc, char **argv)
{
    if (argc == 4 && strcmp(argv[1], "inner") == 0)
        return inner(argv[2], atoi(argv[3]));
    self = argv[0];
    char dir[256];
    snprintf(dir, sizeof dir, "%s/rgl-cleanup.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(dir)) {
        perror(dir);
        return 1;
    }
    char file[300];
    snprintf(file, sizeof file, "%s/partial", dir);

    int st = run(exit_during_stop, file, 0);
    if (!(WIFSIGNALED(st) && WTERMSIG(st) == SIGINT))
        fprintf(stderr, "exit during a stop: %s %d, expected signal %d\n",
                WIFSIGNALED(st) ? "signal" : "exit status",
                WIFSIGNALED(st) ? WTERMSIG(st) : WEXITSTATUS(st), SIGINT);
    CHECK(WIFSIGNALED(st) && WTERMSIG(st) == SIGINT);
    CHECK(access(file, F_OK) != 0);
    unlink(file);

    for (int locked = 0; locked < 2; locked++) {
        st = run(plain_exit, file, locked);
        CHECK(WIFEXITED(st) && WEXITSTATUS(st) == 7);
        unlink(file);
    }

    char said[320];
    snprintf(said, sizeof said, "%s/said", dir);
    said_path = said;
    for (int check = 0; check < 2; check++) {
        st = run(stop_pending, file, check);
        if (!(WIFSIGNALED(st) && WTERMSIG(st) == SIGINT))
            fprintf(stderr, "a stop pending (%s): %s %d, expected signal %d\n",
                    check ? "cleanup_check" : "exit", WIFSIGNALED(st) ? "signal" : "exit status",
                    WIFSIGNALED(st) ? WTERMSIG(st) : WEXITSTATUS(st), SIGINT);
        CHECK(WIFSIGNALED(st) && WTERMSIG(st) == SIGINT);
        CHECK(access(file, F_OK) != 0);
        struct stat sb;
        CHECK(stat(said, &sb) == 0 && sb.st_size == 1);
        unlink(file);
        unlink(said);
    }

    st = run(nested, file, 0);
    CHECK(WIFSIGNALED(st) && WTERMSIG(st) == SIGINT);
    CHECK(access(file, F_OK) != 0);
    unlink(file);
    rmdir(dir);
    return CHECK_RESULT("cleanup");
}
