/* cleanup.h: what a stop signal undoes.
 *
 * SIGINT, SIGTERM and SIGHUP (Ctrl-C to the process or its group, kill, a
 * closed terminal) end raygl2pov, raygl-render and raygl-compare; what
 * they leave must be complete files only. cleanup_start blocks those
 * signals in the calling thread, and so in every thread it creates later,
 * and starts a thread that waits for them. On one, that thread takes the
 * registry's lock for good, then the signal, stops the registered
 * children (SIGTERM, then SIGKILL after 10 s) and waits for them, removes
 * the registered files, then the registered folders, and ends the process
 * by the signal. An exit (exit(), a return from main) waits for a stop
 * under way and acts on a stop signal pending, so the process still ends
 * by the signal with nothing left; once an exit has begun, a later stop
 * signal is not acted on.
 *
 * A temporary file (or a child that writes one) is registered before it
 * is made, and made with the lock held, so nothing is made after the
 * removal. Without cleanup_start the registry is kept and never used.
 */
#ifndef RGL_CLEANUP_H
#define RGL_CLEANUP_H

#include <spawn.h>
#include <sys/types.h>

/* Blocks the stop signals here and starts the waiting thread; call from
 * the main thread before any other thread exists. Returns 0 or -1. */
int cleanup_start(void);

/* The registry's lock (recursive): hold it while making what was
 * registered, so a stop cannot fall between the two. */
void cleanup_lock(void);
void cleanup_unlock(void);

/* Acts on a stop signal that has come and is not yet acted on: this
 * thread stops the process as the waiting thread would (the call does not
 * return); else returns at once. The waiting thread takes a signal only
 * with the lock held, so a thread holding the lock sees the stop coming
 * or none: one that saw a stop's effect first (a child ended by the
 * Ctrl-C to the group) calls it, holding the lock, before acting on it,
 * and the stop finds the state from before. */
void cleanup_check(void);

/* Registers a file to remove (cleanup_file), an empty folder to remove
 * after the files (cleanup_dir), or a child to stop and wait for before
 * anything is removed (cleanup_child; cleanup_tool for a child that is
 * one of these tools: it has 20 s, time to stop its own children and
 * remove its own files). The path is copied. Returns an id for
 * cleanup_drop, or -1 when out of memory. Thread-safe. */
long cleanup_file(const char *path);
long cleanup_dir(const char *path);
long cleanup_child(pid_t pid);
long cleanup_tool(pid_t pid);

/* Forgets entry id (the file renamed into place or removed, the child
 * waited for); -1 is ignored. Thread-safe. */
void cleanup_drop(long id);

/* What the stop says once it has stopped the children and removed the
 * files, just before the process ends by the signal: fn(sig) runs on the
 * waiting thread with the registry's lock held (fn must not register or
 * drop anything). NULL: nothing. The last one set counts; one set while
 * a stop is under way waits for it (the stop says what it began with). */
void cleanup_on_stop(void (*fn)(int sig));

/* A child's start: the stop signals unblocked and at their defaults, so
 * Ctrl-C reaches it as if started from the shell. For posix_spawn (the
 * attributes' mask and defaults are set), and for a forked child before
 * exec (async-signal-safe). */
void cleanup_spawnattr(posix_spawnattr_t *attr);
void cleanup_child_signals(void);

#endif
