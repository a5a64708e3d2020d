/* test_roundtrip.c: encode, decode, compare, re-encode, over every row.
 *
 * For each row of commands.def, many commands with deterministic random
 * arguments valid for their types (extremes included: integer limits, NaN
 * payloads, infinities, -0, subnormals, arrays of 0 and RGL_ARRAY_MAX
 * elements, strings of RGL_STRING_MAX bytes): the encoded bytes decode to the
 * same fields, bit for bit, and re-encode to the same bytes. Then all the
 * commands at once as one sequence: offsets and indices follow, and the
 * encoder refuses what breaks a descriptor.
 */
#include "testutil.h"

#include <stdlib.h>

#define ITERATIONS 200

static bool same_bits(double a, double b) { return rgl_f64_bits(a) == rgl_f64_bits(b); }

static bool same_cmd(const rgl_cmd *a, const rgl_cmd *b)
{
    if (a->opcode != b->opcode || a->nargs != b->nargs || b->info != rgl_cmd_info_get(a->opcode))
        return false;
    for (uint32_t i = 0; i < a->nargs; i++) {
        const rgl_arg *x = &a->arg[i], *y = &b->arg[i];
        if (x->kind != y->kind || x->type != y->type || x->count != y->count)
            return false;
        switch (x->kind) {
        case RGL_ARG_SCALAR:
            if (x->type == RGL_T_f || x->type == RGL_T_d) {
                if (!same_bits(x->v.f, y->v.f))
                    return false;
            } else if (x->v.u != y->v.u) {
                return false;
            }
            break;
        case RGL_ARG_ARRAY:
        case RGL_ARG_COUNTED:
            for (uint32_t k = 0; k < x->count; k++)
                if (!same_bits(x->array[k], y->array[k]))
                    return false;
            break;
        default:
            if (x->count && memcmp(x->bytes, y->bytes, x->count) != 0)
                return false;
            break;
        }
    }
    return true;
}

static uint8_t buf[1 << 20], again[1 << 16];

int main(void)
{
    static rgl_cmd cmd, back;
    size_t nrows, total = 0, len = 0;
    const rgl_cmd_info *const *all = rgl_cmd_info_all(&nrows);
    rng r = {0x0123456789abcdefull};
    rgl_cmd_iter it;

    for (size_t row = 0; row < nrows; row++) {
        unsigned ok = 0;
        for (int n = 0; n < ITERATIONS; n++) {
            size_t size, size2;
            random_cmd(&r, &cmd, all[row]->opcode);
            size = rgl_cmd_encode(&cmd, again, sizeof again);
            if (!CHECK(size > 0))
                continue;
            rgl_cmd_iter_init(&it, again, size, 0);
            if (!CHECK(rgl_cmd_next(&it, &back) == RGL_OK)) {
                fprintf(stderr, "    %s: %s @%llu: %s\n", all[row]->name,
                        rgl_status_str(it.error.status), (unsigned long long)it.error.offset,
                        it.error.detail);
                continue;
            }
            CHECK(rgl_cmd_next(&it, &back) == RGL_END);
            rgl_cmd_iter_init(&it, again, size, 0);
            rgl_cmd_next(&it, &back);
            CHECKF(same_cmd(&cmd, &back), "%s: decoded fields differ", all[row]->name);
            size2 = rgl_cmd_encode(&back, buf, sizeof buf);
            CHECKF(size2 == size && memcmp(buf, again, size) == 0, "%s: re-encode differs",
                   all[row]->name);
            /* Every shorter prefix is truncated, never read past. */
            if (n == 0)
                for (size_t cut = 0; cut < size; cut++) {
                    rgl_cmd_iter_init(&it, again, cut, 0);
                    rgl_status st = rgl_cmd_next(&it, &back);
                    CHECK(cut == 0 ? st == RGL_END : st == RGL_E_TRUNCATED);
                }
            /* An output buffer one byte short is refused. */
            CHECK(rgl_cmd_encode(&cmd, buf, size - 1) == 0);
            ok++;
            total++;
        }
        CHECKF(ok == ITERATIONS, "%s: %u of %d round trips", all[row]->name, ok, ITERATIONS);
    }
    printf("  %zu rows x %d commands: encode, decode, same fields, re-encode byte-identical\n",
           nrows, ITERATIONS);

    /* Every row once, as one sequence. */
    size_t *starts = calloc(nrows, sizeof *starts); /* one per row of the table */
    if (!CHECK(starts != NULL))
        return 1;
    for (size_t row = 0; row < nrows; row++) {
        random_cmd(&r, &cmd, all[row]->opcode);
        starts[row] = len;
        len += rgl_cmd_encode(&cmd, buf + len, sizeof buf - len);
    }
    rgl_cmd_iter_init(&it, buf, len, 5000);
    for (size_t row = 0; row < nrows; row++) {
        if (!CHECK(rgl_cmd_next(&it, &back) == RGL_OK))
            break;
        CHECK(back.opcode == all[row]->opcode && back.index == row);
        CHECK(back.offset == 5000 + starts[row]);
    }
    CHECK(rgl_cmd_next(&it, &back) == RGL_END && rgl_cmd_next(&it, &back) == RGL_END);
    printf("  all %zu rows in one sequence of %zu bytes: order, indices, offsets\n", nrows, len);
    /* The same sequence stepped over with rgl_cmd_skip_floats where it
     * may: exactly the all-float calls (no records), to where rgl_cmd_next goes, and a
     * float row cut short is left to rgl_cmd_next. */
    rgl_cmd_iter skip;
    rgl_cmd_iter_init(&skip, buf, len, 5000);
    size_t nskipped = 0;
    for (size_t row = 0; row < nrows; row++) {
        const rgl_cmd_info *info = all[row];
        bool floats = info->nargs > 0 && info->opcode < 0x80 && info->api != RGL_API_REC;
        for (uint32_t i = 0; i < info->nargs; i++)
            floats = floats && info->args[i].kind == RGL_ARG_SCALAR &&
                     info->args[i].type == RGL_T_f;
        const uint8_t *at = skip.pos;
        uint32_t op = rgl_cmd_skip_floats(&skip);
        CHECKF(op == (floats ? info->opcode : 0u), "%s: skip_floats %u", info->name, op);
        CHECKF(rgl_cmd_float_size(info->opcode) == (floats ? 1u + 4u * info->nargs : 0u),
               "%s: float size", info->name);
        if (op) {
            rgl_cmd_iter one;
            rgl_cmd_iter_init(&one, at, (size_t)(buf + len - at), 0);
            CHECK(rgl_cmd_next(&one, &back) == RGL_OK && one.pos == skip.pos);
            CHECK(skip.index == row + 1);
            rgl_cmd_iter_init(&one, at, (size_t)(skip.pos - at) - 1, 0);
            CHECK(rgl_cmd_skip_floats(&one) == 0 && one.pos == at);
            nskipped++;
        } else if (!CHECK(rgl_cmd_next(&skip, &back) == RGL_OK)) {
            break;
        }
    }
    CHECK(nskipped > 0 && rgl_cmd_skip_floats(&skip) == 0 && skip.pos == buf + len);
    /* And run by run with rgl_cmd_skip_float_run: each run of float rows
     * at once, to the next other row's start, indices counted; a run cut
     * short stops before the cut call. */
    rgl_cmd_iter_init(&skip, buf, len, 5000);
    size_t nruns = 0;
    for (size_t row = 0; row < nrows;) {
        size_t run = 0;
        while (row + run < nrows && rgl_cmd_float_size(all[row + run]->opcode))
            run++;
        size_t got = rgl_cmd_skip_float_run(&skip);
        CHECKF(got == run, "row %zu: run of %zu, skipped %zu", row, run, got);
        row += run;
        CHECK(skip.index == row && skip.pos == (row < nrows ? buf + starts[row] : buf + len));
        if (run) {
            nruns++;
            rgl_cmd_iter cut;
            size_t at = starts[row - run], to = row < nrows ? starts[row] : len;
            rgl_cmd_iter_init(&cut, buf + at, to - at - 1, 0);
            CHECK(rgl_cmd_skip_float_run(&cut) == run - 1 && cut.index == run - 1);
            CHECK(rgl_cmd_skip_float_run(&cut) == 0);
        }
        if (row < nrows && !CHECK(rgl_cmd_next(&skip, &back) == RGL_OK))
            break;
        row += row < nrows;
    }
    CHECK(nruns > 0 && rgl_cmd_skip_float_run(&skip) == 0 && skip.pos == buf + len);
    free(starts);

    /* A run of three-float calls (the common size) cut short anywhere in
     * its last call stops before that call. */
    size_t at3[5];
    size_t len3 = 0;
    static const uint32_t ops3[5] = {RGL_OP_Normal3f, RGL_OP_Color3f, RGL_OP_Vertex3f,
                                     RGL_OP_Vertex2f, RGL_OP_Vertex3f};
    for (int i = 0; i < 5; i++) {
        rgl_cmd_init(&cmd, ops3[i]);
        at3[i] = len3;
        len3 += rgl_cmd_encode(&cmd, buf + len3, sizeof buf - len3);
    }
    for (size_t cut = 0; cut <= len3; cut++) {
        rgl_cmd_iter run;
        rgl_cmd_iter_init(&run, buf, cut, 0);
        size_t whole = 0;
        while (whole < 5 && (whole + 1 < 5 ? at3[whole + 1] : len3) <= cut)
            whole++;
        size_t to = whole < 5 ? at3[whole] : len3;
        CHECKF(rgl_cmd_skip_float_run(&run) == whole && run.pos == buf + to,
               "three-float run cut at %zu", cut);
    }

    /* The encoder refuses arguments outside their descriptors. */
    rgl_cmd_init(&cmd, RGL_OP_Color3ub);
    cmd.arg[0].v.u = 256;
    CHECK(rgl_cmd_encode(&cmd, buf, sizeof buf) == 0);
    rgl_cmd_init(&cmd, RGL_OP_Vertex2s);
    cmd.arg[0].v.i = -32769;
    CHECK(rgl_cmd_encode(&cmd, buf, sizeof buf) == 0);
    rgl_cmd_init(&cmd, RGL_OP_Vertex2i);
    cmd.arg[1].v.i = (int64_t)INT32_MAX + 1;
    CHECK(rgl_cmd_encode(&cmd, buf, sizeof buf) == 0);
    rgl_cmd_init(&cmd, RGL_OP_Enable);
    cmd.arg[0].v.u = (uint64_t)UINT32_MAX + 1;
    CHECK(rgl_cmd_encode(&cmd, buf, sizeof buf) == 0);
    rgl_cmd_init(&cmd, RGL_OP_Lightfv);
    cmd.arg[2].count = RGL_ARRAY_MAX + 1;
    CHECK(rgl_cmd_encode(&cmd, buf, sizeof buf) == 0);
    rgl_cmd_init(&cmd, RGL_OP_Vertex3iv);
    ((double *)cmd.arg[0].array)[1] = 0.5; /* not an integer */
    CHECK(rgl_cmd_encode(&cmd, buf, sizeof buf) == 0);
    rgl_cmd_init(&cmd, RGL_OP_Vertex3fv);
    cmd.arg[0].count = 2; /* a fixed array of the wrong size */
    CHECK(rgl_cmd_encode(&cmd, buf, sizeof buf) == 0);
    rgl_cmd_init(&cmd, RGL_OP_FrameBegin);
    cmd.arg[0].count = RGL_STRING_MAX + 1;
    cmd.arg[0].bytes = buf;
    CHECK(rgl_cmd_encode(&cmd, again, sizeof again) == 0);
    CHECK(rgl_cmd_init(&cmd, 0) == RGL_E_OPCODE && rgl_cmd_init(&cmd, 0x3fff) == RGL_E_OPCODE);
    printf("  encoder refuses out-of-range scalars, counts, non-integral elements, long strings\n");
    printf("  %zu round trips\n", total);
    return test_summary("test_roundtrip");
}
