/* e2e_runstat.c: runs one command and writes what it cost (bench/e2e.sh).
 *
 *   e2e_runstat OUT COMMAND [ARGS...]
 *
 * Runs COMMAND (standard streams inherited, PATH searched), waits for it
 * with wait4 and writes one line to OUT:
 *
 *   wall=S user=S sys=S cpu=S maxrss_kb=N status=N
 *
 * wall from CLOCK_MONOTONIC around fork and wait, user and sys from the
 * child's rusage (microseconds, where /usr/bin/time rounds to 10 ms),
 * maxrss_kb its peak resident set (for a command that runs others, the
 * largest of them). Exits with the command's status (128 + signal when a
 * signal ended it), 1 when it could not be run or OUT not written, 2 on
 * bad usage.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double mono(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double tv(struct timeval t) { return (double)t.tv_sec + 1e-6 * (double)t.tv_usec; }

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: e2e_runstat OUT COMMAND [ARGS...]\n");
        return 2;
    }
    FILE *out = fopen(argv[1], "w");
    if (!out) {
        fprintf(stderr, "e2e_runstat: %s: %s\n", argv[1], strerror(errno));
        return 1;
    }
    double t0 = mono();
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "e2e_runstat: fork: %s\n", strerror(errno));
        fclose(out);
        return 1;
    }
    if (pid == 0) {
        execvp(argv[2], argv + 2);
        fprintf(stderr, "e2e_runstat: %s: %s\n", argv[2], strerror(errno));
        _exit(127);
    }
    int st;
    struct rusage ru;
    pid_t r;
    while ((r = wait4(pid, &st, 0, &ru)) < 0 && errno == EINTR)
        ;
    double wall = mono() - t0;
    if (r < 0) {
        fprintf(stderr, "e2e_runstat: wait4: %s\n", strerror(errno));
        fclose(out);
        return 1;
    }
    int status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
    double user = tv(ru.ru_utime), sys = tv(ru.ru_stime);
    fprintf(out, "wall=%.6f user=%.6f sys=%.6f cpu=%.6f maxrss_kb=%ld status=%d\n", wall, user, sys,
            user + sys, ru.ru_maxrss, status);
    if (fclose(out) != 0) {
        fprintf(stderr, "e2e_runstat: %s: %s\n", argv[1], strerror(errno));
        return 1;
    }
    return status;
}
