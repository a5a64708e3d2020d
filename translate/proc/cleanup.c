/* cleanup.c: the stop-signal thread and its registry (cleanup.h). */
#include "cleanup.h"

#include <errno.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <sys/signalfd.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

enum { KIND_FILE = 1, KIND_DIR, KIND_CHILD };

/* How long a child has to end after SIGTERM before SIGKILL, in ms. One of
 * these tools stops its own children in GRACE_MS, then removes its files:
 * it gets twice as long, or it could be killed in the middle. */
enum { GRACE_MS = 10000, TOOL_GRACE_MS = 2 * GRACE_MS };

typedef struct entry {
    int kind; /* 0: free */
    pid_t pid;
    int grace_ms;
    char *path;
} entry;

static pthread_mutex_t lock;
static pthread_once_t lock_once = PTHREAD_ONCE_INIT;
static entry *entries;
static size_t nentries, cap;

static void init_lock(void)
{
    pthread_mutexattr_t a;
    pthread_mutexattr_init(&a);
    pthread_mutexattr_settype(&a, PTHREAD_MUTEX_RECURSIVE);
    pthread_mutex_init(&lock, &a);
    pthread_mutexattr_destroy(&a);
}

void cleanup_lock(void)
{
    pthread_once(&lock_once, init_lock);
    pthread_mutex_lock(&lock);
}

void cleanup_unlock(void)
{
    pthread_mutex_unlock(&lock);
}

static void stop_set(sigset_t *s)
{
    sigemptyset(s);
    sigaddset(s, SIGINT);
    sigaddset(s, SIGTERM);
    sigaddset(s, SIGHUP);
}

static long add(int kind, const char *path, pid_t pid, int grace_ms)
{
    char *copy = NULL;
    if (path) {
        copy = malloc(strlen(path) + 1);
        if (!copy)
            return -1;
        strcpy(copy, path);
    }
    cleanup_lock();
    size_t i = 0;
    while (i < nentries && entries[i].kind)
        i++;
    if (i == nentries) {
        if (nentries == cap) {
            size_t ncap = cap ? cap * 2 : 16;
            entry *e = realloc(entries, ncap * sizeof *e);
            if (!e) {
                cleanup_unlock();
                free(copy);
                return -1;
            }
            entries = e;
            cap = ncap;
        }
        nentries++;
    }
    entries[i].kind = kind;
    entries[i].pid = pid;
    entries[i].grace_ms = grace_ms;
    entries[i].path = copy;
    cleanup_unlock();
    return (long)i;
}

long cleanup_file(const char *path)
{
    return add(KIND_FILE, path, 0, 0);
}

long cleanup_dir(const char *path)
{
    return add(KIND_DIR, path, 0, 0);
}

long cleanup_child(pid_t pid)
{
    return add(KIND_CHILD, NULL, pid, GRACE_MS);
}

long cleanup_tool(pid_t pid)
{
    return add(KIND_CHILD, NULL, pid, TOOL_GRACE_MS);
}

void cleanup_drop(long id)
{
    if (id < 0)
        return;
    cleanup_lock();
    if ((size_t)id < nentries) {
        free(entries[id].path);
        memset(&entries[id], 0, sizeof entries[id]);
    }
    cleanup_unlock();
}

static long ms_since(const struct timespec *t0)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long)(t.tv_sec - t0->tv_sec) * 1000 + (t.tv_nsec - t0->tv_nsec) / 1000000;
}

/* SIGTERM to the registered children, then waits for them all at once: one
 * still there at the end of its grace gets SIGKILL. A pid another thread
 * reaped already gives ECHILD: it is gone too. Forgets each. */
static void stop_children(void)
{
    for (size_t i = 0; i < nentries; i++)
        if (entries[i].kind == KIND_CHILD)
            kill(entries[i].pid, SIGTERM);
    struct timespec t0, tick = {0, 20 * 1000 * 1000};
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (;;) {
        bool left = false;
        long ms = ms_since(&t0);
        for (size_t i = 0; i < nentries; i++) {
            entry *e = &entries[i];
            if (e->kind != KIND_CHILD)
                continue;
            pid_t r = waitpid(e->pid, NULL, WNOHANG);
            if (r == 0 && ms >= e->grace_ms) {
                kill(e->pid, SIGKILL);
                while (waitpid(e->pid, NULL, 0) < 0 && errno == EINTR)
                    ;
            } else if (r == 0 || (r < 0 && errno == EINTR)) {
                left = true;
                continue;
            }
            e->kind = 0;
        }
        if (!left)
            return;
        nanosleep(&tick, NULL);
    }
}

static void (*_Atomic on_stop)(int sig);

/* With the lock: a stop under way keeps the words it began with (the
 * main thread whose waitpid found no child, the stop having reaped them,
 * ends its loop and clears them). */
void cleanup_on_stop(void (*fn)(int sig))
{
    cleanup_lock();
    atomic_store(&on_stop, fn);
    cleanup_unlock();
}

/* The stop itself, with the lock held for good: nothing registered is made
 * from now on. */
_Noreturn static void stop(int sig)
{
    stop_children();
    for (size_t i = nentries; i-- > 0;)
        if (entries[i].kind == KIND_FILE)
            unlink(entries[i].path);
    for (size_t i = nentries; i-- > 0;)
        if (entries[i].kind == KIND_DIR)
            rmdir(entries[i].path);
    void (*fn)(int) = atomic_load(&on_stop);
    if (fn)
        fn(sig);
    /* End by the signal, as the shell expects of Ctrl-C. */
    signal(sig, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, sig);
    pthread_sigmask(SIG_UNBLOCK, &one, NULL);
    raise(sig);
    _exit(128 + sig);
}

/* A stop signal is taken from the pending ones only with the lock held,
 * here or by the waiter (which polls for it without taking it): whoever
 * holds the lock sees it pending or a stop under way, never a signal
 * taken and not yet acted on. */
void cleanup_check(void)
{
    sigset_t set;
    stop_set(&set);
    struct timespec zero = {0, 0};
    cleanup_lock();
    int sig = sigtimedwait(&set, NULL, &zero);
    if (sig > 0)
        stop(sig);
    cleanup_unlock();
}

/* The stop signals as a file that is readable while one is pending. */
static int stop_fd = -1;

static void *waiter(void *arg)
{
    (void)arg;
    for (;;) {
        struct pollfd p = {.fd = stop_fd, .events = POLLIN};
        if (poll(&p, 1, -1) <= 0)
            continue;
        cleanup_lock();
        struct signalfd_siginfo si;
        if (read(stop_fd, &si, sizeof si) == (ssize_t)sizeof si)
            stop((int)si.ssi_signo);
        cleanup_unlock();
    }
    return NULL;
}

/* At exit, in the exiting thread. Another thread may be ending the process
 * while the waiter stops it: the main thread whose waitpid found no child
 * because the waiter reaped it returns from main. Exiting then would cut
 * the removal short. The lock waits for a stop under way, which ends the
 * process by its signal; a stop signal still pending is acted on here;
 * none is after. */
static void at_exit(void)
{
    cleanup_lock(); /* kept */
    cleanup_check();
}

static void ignore(int sig)
{
    (void)sig;
}

int cleanup_start(void)
{
    static bool started;
    if (started)
        return 0;
    sigset_t set;
    stop_set(&set);
    if (pthread_sigmask(SIG_BLOCK, &set, NULL) != 0)
        return -1;
    /* A blocked signal stays pending unless ignored: a program started in
     * the background by a shell inherits SIGINT ignored, yet is stopped by
     * one sent on purpose. */
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = ignore;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
    stop_fd = signalfd(-1, &set, SFD_CLOEXEC | SFD_NONBLOCK);
    if (stop_fd < 0 || atexit(at_exit) != 0)
        return -1;
    pthread_t t;
    pthread_attr_t a;
    pthread_attr_init(&a);
    pthread_attr_setdetachstate(&a, PTHREAD_CREATE_DETACHED);
    int rc = pthread_create(&t, &a, waiter, NULL);
    pthread_attr_destroy(&a);
    if (rc != 0) {
        errno = rc;
        return -1;
    }
    started = true;
    return 0;
}

void cleanup_spawnattr(posix_spawnattr_t *attr)
{
    sigset_t none, stops;
    sigemptyset(&none);
    stop_set(&stops);
    posix_spawnattr_setsigmask(attr, &none);
    posix_spawnattr_setsigdefault(attr, &stops);
    short flags = 0;
    posix_spawnattr_getflags(attr, &flags);
    posix_spawnattr_setflags(attr, flags | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
}

void cleanup_child_signals(void)
{
    sigset_t stops;
    stop_set(&stops);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGHUP, SIG_DFL);
    sigprocmask(SIG_UNBLOCK, &stops, NULL);
}
