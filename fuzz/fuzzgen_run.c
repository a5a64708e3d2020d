/* fuzzgen_run.c: runs the structure-aware mutator for a fixed number of
 * rounds, without libFuzzer, so that it cannot rot.
 *
 * Usage: fuzzgen-run ROUNDS [MAX_SIZE [skip-recursive-lists]]
 *
 * Linked with one fuzz target (fuzz_decode.c or fuzz_translate.c). For seeds
 * 1..ROUNDS it generates a trace, mutates it a few times and crosses it
 * with the previous one, and for every result checks that it fits, that it
 * is a valid trace (no damage, every frame and COMMANDS resource decodes to
 * its end), that the same seed gives the same bytes, and runs the target on
 * it. At the end it checks that the compositions showed up: list bodies
 * that call lists, array draws with @ArrayData, textures with pixels, GLU
 * or GLUT shapes, frames carrying state. Exit 0 when all holds, 1 when not.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "format.h"
#include "fuzzgen.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static struct {
    unsigned long inputs, recursive, list_calls, arrays, textures, shapes, carried, frames2;
} seen;

static bool skip_recursive;

static int fail(unsigned seed, const char *what)
{
    fprintf(stderr, "fuzzgen-run: seed %u: %s\n", seed, what);
    return 1;
}

/* Commands of one sequence; returns false unless it decodes to its end. */
static bool census(const uint8_t *p, size_t n, bool body)
{
    static rgl_cmd cmd;
    rgl_cmd_iter it;
    rgl_status st;
    rgl_cmd_iter_init(&it, p, n, 0);
    while ((st = rgl_cmd_next(&it, &cmd)) == RGL_OK) {
        const char *h = cmd.info->handler;
        seen.list_calls += body && (cmd.opcode == RGL_OP_CallList || cmd.opcode == RGL_OP_CallLists);
        seen.arrays += cmd.opcode == RGL_OP_ArrayData;
        seen.textures += cmd.opcode == RGL_OP_TexImage2D || cmd.opcode == RGL_OP_Build2DMipmaps;
        seen.shapes += strncmp(h, "glut", 4) == 0 || strcmp(h, "glusphere") == 0 ||
                       strcmp(h, "glucylinder") == 0 || strcmp(h, "gludisk") == 0;
    }
    return st == RGL_END;
}

/* True when some display list can reach itself through calls (or any body
 * uses glCallLists, which can name any list): the list bombs that the
 * translator's frame budget bounds, at a cost of seconds each, so the run
 * leaves them out of the target (tests/translate/crashers holds some). */
static bool lists_recurse(rgl_reader *r)
{
    enum { MAXL = 64 };
    static rgl_cmd cmd;
    uint32_t name[MAXL], body[MAXL];
    bool edge[MAXL][MAXL] = {{false}}, any = false;
    size_t n = 0;
    /* list definitions: glNewList in frames and in bodies */
    for (size_t pass = 0; pass < 2; pass++)
        for (size_t i = 0; i < (pass ? rgl_reader_resource_count(r) : rgl_reader_frame_count(r));
             i++) {
            rgl_frame_info f;
            rgl_resource res;
            rgl_cmd_iter it;
            if (pass ? rgl_reader_resource_at(r, i, &res, NULL) != RGL_OK ||
                           res.kind != RGL_RES_COMMANDS
                     : rgl_reader_frame(r, i, &f, NULL) != RGL_OK)
                continue;
            rgl_cmd_iter_init(&it, pass ? res.data : f.commands,
                              pass ? res.size : f.commands_size, 0);
            while (rgl_cmd_next(&it, &cmd) == RGL_OK)
                if (cmd.opcode == RGL_OP_NewList && n < MAXL) {
                    name[n] = (uint32_t)cmd.arg[0].v.u;
                    body[n++] = (uint32_t)cmd.arg[2].v.u;
                }
        }
    for (size_t i = 0; i < n; i++) {
        rgl_resource res;
        rgl_cmd_iter it;
        if (rgl_reader_resource(r, body[i], &res, NULL) != RGL_OK || res.kind != RGL_RES_COMMANDS)
            continue;
        rgl_cmd_iter_init(&it, res.data, res.size, 0);
        while (rgl_cmd_next(&it, &cmd) == RGL_OK)
            for (size_t j = 0; j < n; j++)
                if (cmd.opcode == RGL_OP_CallLists ||
                    (cmd.opcode == RGL_OP_CallList && cmd.arg[0].v.u == name[j]))
                    edge[i][j] = true;
    }
    /* transitive closure (n is small): a list that reaches itself */
    for (size_t k = 0; k < n; k++)
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++)
                edge[i][j] = edge[i][j] || (edge[i][k] && edge[k][j]);
    for (size_t i = 0; i < n; i++)
        any = any || edge[i][i];
    return any;
}

static int check_trace(unsigned seed, const uint8_t *data, size_t size, size_t max)
{
    rgl_reader *r = NULL;
    rgl_error err;
    if (!size || size > max)
        return fail(seed, "no output, or too large");
    if (rgl_reader_open_memory(data, size, &r, &err) != RGL_OK)
        return fail(seed, "not a trace");
    int bad = rgl_reader_damage_count(r) != 0;
    for (size_t i = 0; i < rgl_reader_frame_count(r) && !bad; i++) {
        rgl_frame_info f;
        bad = rgl_reader_frame(r, i, &f, &err) != RGL_OK ||
              !census(f.commands, f.commands_size, false);
        seen.carried += (f.flags & RGL_FRAME_STATE_CARRIED) != 0;
        seen.frames2 += i == 1;
    }
    for (size_t i = 0; i < rgl_reader_resource_count(r) && !bad; i++) {
        rgl_resource res;
        bad = rgl_reader_resource_at(r, i, &res, &err) != RGL_OK ||
              (res.kind == RGL_RES_COMMANDS && !census(res.data, res.size, true));
    }
    bool recursive = lists_recurse(r);
    rgl_reader_destroy(r);
    if (bad)
        return fail(seed, "damaged trace, or a sequence that does not decode");
    seen.inputs++;
    if (getenv("FUZZGEN_OUT")) { /* keep the inputs, to look at or replay */
        char path[4096];
        snprintf(path, sizeof path, "%s/gen-%u-%lu.bin", getenv("FUZZGEN_OUT"), seed, seen.inputs);
        FILE *f = fopen(path, "wb");
        if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0)
            return fail(seed, "cannot write to FUZZGEN_OUT");
    }
    seen.recursive += recursive;
    if (!(recursive && skip_recursive) && !getenv("FUZZGEN_NO_TARGET"))
        LLVMFuzzerTestOneInput(data, size);
    return 0;
}

int main(int argc, char **argv)
{
    unsigned long rounds = argc > 1 ? strtoul(argv[1], NULL, 10) : 0;
    size_t max = argc > 2 ? strtoul(argv[2], NULL, 10) : 4096;
    uint8_t *cur = malloc(max), *again = malloc(max), *prev = malloc(max), *mix = malloc(max);
    size_t prev_size = 0;
    int failed = 0;

    skip_recursive = argc > 3 && strcmp(argv[3], "skip-recursive-lists") == 0;
    if (argc < 2 || argc > 4 || !rounds || max < 256 || (argc > 3 && !skip_recursive)) {
        fprintf(stderr, "usage: fuzzgen-run ROUNDS [MAX_SIZE [skip-recursive-lists]]\n");
        return 2;
    }
    if (!cur || !again || !prev || !mix)
        return 1;
    for (unsigned seed = 1; seed <= rounds && !failed; seed++) {
        size_t n = fuzzgen_generate(cur, max, seed);
        if (fuzzgen_generate(again, max, seed) != n || memcmp(cur, again, n) != 0)
            failed = fail(seed, "generate is not deterministic");
        else
            failed = check_trace(seed, cur, n, max);
        for (unsigned k = 0; k < 4 && !failed; k++) {
            uint32_t ms = seed * 16 + k;
            memcpy(again, cur, n);
            size_t m = fuzzgen_mutate(cur, n, max, ms, NULL);
            if (fuzzgen_mutate(again, n, max, ms, NULL) != m || memcmp(cur, again, m) != 0)
                failed = fail(seed, "mutate is not deterministic");
            else
                failed = check_trace(seed, cur, n = m, max);
        }
        if (!failed && prev_size) {
            size_t m = fuzzgen_crossover(cur, n, prev, prev_size, mix, max, seed);
            if (m)
                failed = check_trace(seed, mix, m, max);
        }
        memcpy(prev, cur, n);
        prev_size = n;
    }
    printf("fuzzgen-run: %lu traces (%lu with recursive lists); list calls in bodies %lu, @ArrayData %lu, textures %lu, "
           "shapes %lu, carried frames %lu\n",
           seen.inputs, seen.recursive, seen.list_calls, seen.arrays, seen.textures, seen.shapes, seen.carried);
    if (!failed && (!seen.list_calls || !seen.arrays || !seen.textures || !seen.shapes ||
                    !seen.carried || !seen.frames2))
        failed = fail(0, "a composition never showed up");
    free(cur);
    free(again);
    free(prev);
    free(mix);
    return failed;
}
