/* test_alloc.c: every allocation of format/ failing in turn.
 *
 * Builds the sample trace and opens it (with and without index, from memory
 * and from a file) with the n-th allocation failing, for every n until the
 * whole run needs no failure: each attempt ends with RGL_E_NOMEM (or NULL
 * from a create) and no crash; under AddressSanitizer, no leak either.
 */
#include <unistd.h>

#include "testutil.h"

/* One full run; returns true when it succeeded end to end. */
static bool run(bool with_index, const char *path, unsigned long *nomem)
{
    sample s;
    rgl_reader *rd = NULL;
    rgl_error err;
    bool ok = sample_build(&s, with_index, 5);
    if (!ok) {
        (*nomem)++;
        rgl_trace_builder_destroy(s.builder);
        return false;
    }
    rgl_status st = rgl_reader_open_memory(s.data, s.size, &rd, &err);
    if (st == RGL_OK) {
        ok = rgl_reader_frame_count(rd) == SAMPLE_FRAMES;
        rgl_reader_destroy(rd);
        rd = NULL;
        FILE *f = fopen(path, "wb");
        if (f) {
            fwrite(s.data, 1, s.size, f);
            fclose(f);
        }
        st = rgl_reader_open_file(path, &rd, &err);
    }
    if (st != RGL_OK) {
        CHECKF(st == RGL_E_NOMEM && rd == NULL, "open: %s", rgl_status_str(st));
        (*nomem)++;
        ok = false;
    }
    rgl_reader_destroy(rd);
    rgl_trace_builder_destroy(s.builder);
    return ok;
}

int main(void)
{
    char path[] = "/tmp/rgl-alloc-XXXXXX";
    int fd = mkstemp(path);
    close(fd);
    for (int with_index = 0; with_index < 2; with_index++) {
        unsigned long n, nomem = 0;
        for (n = 1; n < 10000; n++) {
            rgl_format_fail_alloc(n);
            bool ok = run(with_index, path, &nomem);
            rgl_format_fail_alloc(0);
            if (ok)
                break;
        }
        CHECK(n < 10000 && nomem == n - 1);
        printf("  %s: allocations 1..%lu failed in turn, each a clean RGL_E_NOMEM\n",
               with_index ? "with index" : "no index", n - 1);
    }
    unlink(path);
    return test_summary("test_alloc");
}
