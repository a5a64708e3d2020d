/* test_damage.c: damaged traces, exhaustively on a small one.
 *
 * The sample trace (with and without index) cut at every byte offset, and
 * with every byte flipped (three ways): opening never crashes; every frame
 * and resource whose chunk the damage does not touch still reads, with its
 * exact bytes; and every error reported (damage found while opening, or a
 * checksum failure when a frame or resource is fetched) names an offset
 * inside the damaged chunk (or the file header).
 */
#include "testutil.h"

static uint8_t buf[1 << 16];

/* Index of the chunk holding byte `at`, or -1 for the file header. */
static int chunk_of(const chunk_span *sp, size_t n, uint64_t at)
{
    for (size_t i = 0; i < n; i++)
        if (at >= sp[i].start && at < sp[i].end)
            return (int)i;
    return -1;
}

static unsigned long runs, frames_read;

/* Checks a reader over damaged bytes [lo, hi): the damaged chunk spans
 * [dlo, dhi). Frames and resources outside it must read. */
static void check_after_damage(const sample *s, const chunk_span *sp, size_t nsp,
                               const uint8_t *d, size_t size, uint64_t dlo, uint64_t dhi,
                               const char *what, uint64_t where)
{
    rgl_reader *rd;
    rgl_error err;
    rgl_status st = rgl_reader_open_memory(d, size, &rd, &err);
    runs++;
    if (st != RGL_OK) {
        /* Only a damaged file header may stop the open. */
        CHECKF(dlo == 0 && err.offset < RGL_FILE_HEADER_SIZE + 1, "%s at %llu: open failed: %s",
               what, (unsigned long long)where, rgl_status_str(st));
        return;
    }
    for (size_t i = 0; i < rgl_reader_damage_count(rd); i++) {
        const rgl_error *e = rgl_reader_damage(rd, i);
        CHECKF(e->offset >= dlo && e->offset <= dhi,
               "%s at %llu: damage reported at %llu, outside [%llu, %llu]: %s", what,
               (unsigned long long)where, (unsigned long long)e->offset,
               (unsigned long long)dlo, (unsigned long long)dhi, e->detail);
    }
    /* Sample frame f is chunk 1 + SAMPLE_RESOURCES + f; resource i is chunk 1 + i.
     * A listed frame either reads (and is then an intact one, exactly) or
     * fails with an offset inside the damage. */
    bool seen[SAMPLE_FRAMES] = {false};
    for (size_t i = 0; i < rgl_reader_frame_count(rd); i++) {
        rgl_frame_info fi;
        if (rgl_reader_frame(rd, i, &fi, &err) != RGL_OK) {
            CHECKF(err.offset >= dlo && err.offset <= dhi,
                   "%s at %llu: frame %zu error at %llu outside damage: %s", what,
                   (unsigned long long)where, i, (unsigned long long)err.offset, err.detail);
            continue;
        }
        size_t f = 0;
        while (f < SAMPLE_FRAMES && sp[1 + SAMPLE_RESOURCES + f].start != fi.offset)
            f++;
        if (!CHECKF(f < SAMPLE_FRAMES, "%s at %llu: frame at unexpected offset %llu", what,
                    (unsigned long long)where, (unsigned long long)fi.offset))
            continue;
        CHECKF(sample_frame_ok(s, rd, i, f), "%s at %llu: frame %zu reads wrong", what,
               (unsigned long long)where, f);
        seen[f] = true;
    }
    for (size_t f = 0; f < SAMPLE_FRAMES; f++) {
        const chunk_span *c = &sp[1 + SAMPLE_RESOURCES + f];
        if (c->end <= size && (c->end <= dlo || c->start >= dhi)) {
            CHECKF(seen[f], "%s at %llu: intact frame %zu lost", what, (unsigned long long)where,
                   f);
            frames_read++;
        }
    }
    for (int i = 0; i < SAMPLE_RESOURCES; i++) {
        const chunk_span *c = &sp[1 + i];
        rgl_resource res;
        rgl_status rs = rgl_reader_resource(rd, s->res_id[i], &res, &err);
        if (c->end <= size && (c->end <= dlo || c->start >= dhi))
            CHECKF(rs == RGL_OK && res.size == s->res_len[i] &&
                       memcmp(res.data, s->res_bytes[i], res.size) == 0,
                   "%s at %llu: intact resource %d lost", what, (unsigned long long)where, i);
        else if (rs != RGL_OK && rs != RGL_E_RESOURCE)
            CHECKF(err.offset >= dlo && err.offset <= dhi, "%s at %llu: resource error outside",
                   what, (unsigned long long)where);
    }
    rgl_reader_destroy(rd);
    (void)nsp;
}

int main(void)
{
    static const uint8_t masks[] = {0x01, 0x80, 0xff};
    for (int with_index = 0; with_index < 2; with_index++) {
        sample s;
        chunk_span sp[32];
        size_t n;
        CHECK(sample_build(&s, with_index, 21));
        n = chunk_spans(s.data, s.size, sp, 32);
        CHECK(n == 1 + SAMPLE_RESOURCES + SAMPLE_FRAMES + (with_index ? 2 : 0));

        /* Truncation at every offset: the damaged chunk is the cut one. */
        for (size_t cut = 0; cut <= s.size; cut++) {
            int k = chunk_of(sp, n, cut);
            uint64_t dlo = k < 0 ? (cut < RGL_FILE_HEADER_SIZE ? 0 : cut) : sp[k].start;
            memcpy(buf, s.data, cut);
            check_after_damage(&s, sp, n, buf, cut, dlo, cut, "truncated", cut);
        }
        /* Every byte flipped, three ways. */
        for (size_t at = 0; at < s.size; at++) {
            for (size_t m = 0; m < sizeof masks; m++) {
                int k = chunk_of(sp, n, at);
                uint64_t dlo = k < 0 ? 0 : sp[k].start;
                uint64_t dhi = k < 0 ? RGL_FILE_HEADER_SIZE : sp[k].end;
                memcpy(buf, s.data, s.size);
                buf[at] ^= masks[m];
                check_after_damage(&s, sp, n, buf, s.size, dlo, dhi, "flipped", at);
            }
        }
        printf("  %s: cut at all %zu offsets, each of %zu bytes flipped 3 ways\n",
               with_index ? "with index" : "no index", s.size + 1, s.size);
        rgl_trace_builder_destroy(s.builder);
    }
    printf("  %lu damaged traces opened, %lu intact frames read back exactly\n", runs,
           frames_read);
    return test_summary("test_damage");
}
