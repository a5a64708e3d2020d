/* session.c: what `raygl record` asks of the recorder through the
 * environment beyond the frame selection (recorder.c), the same in
 * libraygl and in libraygl-preload.so: a program built with the drop-in
 * header is recorded by the libraygl it links, and the preload library
 * stands down (preload.c).
 *
 * - RAYGL_STATUS_FILE: a file `raygl record` made and reads once the
 *   program has ended. Each recording process of the run appends a line:
 *   "failed" when its trace could not be written or recording stopped
 *   early, "exit" when RAYGL_EXIT ended it with the trace closed.
 * - RAYGL_EXIT=1: once the thread's stream has ended the last frame the
 *   selection can keep, the trace is closed (every kept frame and the
 *   index on disk), then the process is sent SIGTERM, and SIGKILL
 *   RGL_EXIT_GRACE_S seconds later. Closing first means that however the
 *   program ends (its own SIGTERM handler, SIGKILL), the trace is whole.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "raygl.h"
#include "recorder.h"

/* Seconds between RAYGL_EXIT's SIGTERM and its SIGKILL (docs/raygl.1). */
#define RGL_EXIT_GRACE_S 3

static char status_path[PATH_MAX];
static bool exit_after;

void rgl_session_init(void)
{
    const char *v = getenv("RAYGL_STATUS_FILE");
    if (v && *v && strlen(v) < sizeof status_path)
        strcpy(status_path, v);
    v = getenv("RAYGL_EXIT");
    exit_after = v && strcmp(v, "1") == 0;
}

static void status_line(const char *line)
{
    if (!status_path[0])
        return;
    int e = errno;
    /* No O_CREAT: a process that outlives raygl record finds no file. */
    int fd = open(status_path, O_WRONLY | O_APPEND | O_CLOEXEC | O_NOCTTY);
    if (fd >= 0) {
        ssize_t r = write(fd, line, strlen(line));
        (void)r;
        close(fd);
    }
    errno = e;
}

void rgl_session_failed(void) { status_line("failed\n"); }

static void *exit_reaper(void *arg)
{
    (void)arg;
    struct timespec t = {RGL_EXIT_GRACE_S, 0};
    while (nanosleep(&t, &t) != 0 && errno == EINTR)
        ;
    kill(getpid(), SIGKILL);
    return NULL;
}

void rgl_session_selection_over(void)
{
    static atomic_bool started;
    if (!exit_after || atomic_exchange(&started, true))
        return;
    int e = errno;
    rayglRecordClose();
    status_line("exit\n");
    /* The reaper blocks every signal, so none of the program's lands on it. */
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &old);
    pthread_attr_t attr;
    if (pthread_attr_init(&attr) == 0) {
        pthread_t t;
        pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
        pthread_create(&t, &attr, exit_reaper, NULL);
        pthread_attr_destroy(&attr);
    }
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    kill(getpid(), SIGTERM);
    errno = e;
}
