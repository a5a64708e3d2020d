/* replay.c: runs a fuzz target over files, without libFuzzer.
 *
 * Usage: fuzz-replay PATH...  where each PATH is a file or a directory of
 * files (not recursive). Every input goes through LLVMFuzzerTestOneInput, as
 * under the fuzzer; a failed check aborts. This is how the seed corpus and
 * every minimised crasher run in each `meson test`. Linked with each fuzz
 * target (format's fuzz-replay, the translator's fuzz-translate-replay); the
 * messages carry the program's own name.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char *prog = "fuzz-replay";

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

static int replay_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf = NULL;
    size_t size = 0, cap = 0, n;
    if (!f) {
        fprintf(stderr, "%s: %s: cannot open\n", prog, path);
        return -1;
    }
    do {
        if (size == cap) {
            unsigned char *nb = realloc(buf, cap ? cap * 2 : 4096);
            if (!nb) {
                free(buf);
                fclose(f);
                return -1;
            }
            buf = nb;
            cap = cap ? cap * 2 : 4096;
        }
        n = fread(buf + size, 1, cap - size, f);
        size += n;
    } while (n > 0);
    fclose(f);
    LLVMFuzzerTestOneInput(buf, size);
    free(buf);
    return 0;
}

int main(int argc, char **argv)
{
    unsigned long count = 0, failed = 0;
    if (argc > 0 && argv[0][0]) {
        const char *slash = strrchr(argv[0], '/');
        prog = slash ? slash + 1 : argv[0];
    }
    for (int i = 1; i < argc; i++) {
        struct stat sb;
        if (stat(argv[i], &sb) != 0) {
            fprintf(stderr, "%s: %s: not found\n", prog, argv[i]);
            failed++;
            continue;
        }
        if (!S_ISDIR(sb.st_mode)) {
            failed += replay_file(argv[i]) != 0;
            count++;
            continue;
        }
        DIR *d = opendir(argv[i]);
        struct dirent *e;
        if (!d) {
            failed++;
            continue;
        }
        while ((e = readdir(d))) {
            char path[4096];
            if (e->d_name[0] == '.')
                continue;
            snprintf(path, sizeof path, "%s/%s", argv[i], e->d_name);
            if (stat(path, &sb) != 0 || !S_ISREG(sb.st_mode))
                continue;
            failed += replay_file(path) != 0;
            count++;
        }
        closedir(d);
    }
    printf("%s: %lu inputs replayed, %lu unreadable\n", prog, count, failed);
    return failed || count == 0 ? 1 : 0;
}
