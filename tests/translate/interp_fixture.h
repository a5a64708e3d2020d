/* interp_fixture.h: the fixture the translate tests share.
 *
 * One scene and diagnostic log (sc, dlog), an interpreter on them fresh
 * each test (fresh), a command sequence run and freed (run), the count of a
 * diagnostic (count), resources the interpreter fetches, and the SDL of the
 * scene kept in memory (sdl, nsdl; write_sdl).
 *
 * A test includes check.h first: run and write_sdl check with its CHECK.
 *
 * Resources: a test sets fx_fetch before fresh() to fetch_bodies (id k is
 * bodies[k - 1], a command body read at fetch time) or fetch_res (id k is
 * res[k - 1], bytes or commands); NULL (the default) sets none.
 */
#ifndef RGL_TEST_INTERP_FIXTURE_H
#define RGL_TEST_INTERP_FIXTURE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "interp.h"
#include "outbuf.h"
#include "povwrite.h"
#include "tracegen.h"

extern scene sc;
extern diag_log dlog;

#define FX_MAX_BODIES 8
#define FX_MAX_RES 16
extern seq bodies[FX_MAX_BODIES];
extern size_t nbodies;

typedef struct res_item {
    uint32_t kind;
    uint8_t *data;
    size_t size;
} res_item;
extern res_item res[FX_MAX_RES];
extern size_t nres;

extern interp_resource_fn fx_fetch;
rgl_status fetch_bodies(void *ctx, uint32_t id, rgl_resource *out, rgl_error *err);
rgl_status fetch_res(void *ctx, uint32_t id, rgl_resource *out, rgl_error *err);

uint32_t add_body(seq *s);      /* into bodies; free_bodies frees them */
void free_bodies(void);
uint32_t add_bytes(const void *p, size_t n); /* a copy, into res */
uint32_t add_res_body(seq *s);  /* s's bytes as commands, into res (owned) */
void free_res(void);

/* The fixture's steps return false where the test's CHECK (whose count is
 * the test file's own) should fail; these macros check them there. */
bool fx_run(interp *ip, seq *s);
bool fx_write_sdl(povwriter *w, const pov_frame_info *info);
#define run(ip, s) CHECK(fx_run((ip), (s)))
/* The SDL of sc by w (a writer of its own when NULL) with info, in sdl. */
#define write_sdl_with(w, info) CHECK(fx_write_sdl((w), (info)))
#define write_sdl() write_sdl_with(NULL, NULL)

interp *fresh(void);
uint64_t count(diag_kind k);

#define FX_SDL_SIZE (1 << 16)
extern char sdl[FX_SDL_SIZE];
extern size_t nsdl;
int keep(void *user, const char *p, size_t n);
size_t occurrences(const char *hay, const char *needle);

#endif
