/* interp_fixture.c: the translate tests' shared fixture (interp_fixture.h). */
#include "interp_fixture.h"

#include <stdlib.h>
#include <string.h>

scene sc;
diag_log dlog;

seq bodies[FX_MAX_BODIES];
size_t nbodies;
res_item res[FX_MAX_RES];
size_t nres;
interp_resource_fn fx_fetch;

char sdl[FX_SDL_SIZE];
size_t nsdl;

static rgl_status serve(uint32_t id, uint32_t kind, const uint8_t *data, size_t size,
                        rgl_resource *out)
{
    memset(out, 0, sizeof *out);
    out->id = id;
    out->kind = kind;
    out->data = data;
    out->size = size;
    return RGL_OK;
}

rgl_status fetch_bodies(void *ctx, uint32_t id, rgl_resource *out, rgl_error *err)
{
    (void)ctx;
    if (id == 0 || id > nbodies) {
        err->status = RGL_E_RESOURCE;
        return RGL_E_RESOURCE;
    }
    return serve(id, RGL_RES_COMMANDS, bodies[id - 1].data, bodies[id - 1].len, out);
}

rgl_status fetch_res(void *ctx, uint32_t id, rgl_resource *out, rgl_error *err)
{
    (void)ctx;
    if (id == 0 || id > nres) {
        err->status = RGL_E_RESOURCE;
        return RGL_E_RESOURCE;
    }
    return serve(id, res[id - 1].kind, res[id - 1].data, res[id - 1].size, out);
}

uint32_t add_body(seq *s)
{
    bodies[nbodies] = *s;
    return (uint32_t)++nbodies;
}

void free_bodies(void)
{
    for (size_t i = 0; i < nbodies; i++)
        seq_free(&bodies[i]);
    nbodies = 0;
}

uint32_t add_bytes(const void *p, size_t n)
{
    res[nres].kind = RGL_RES_BYTES;
    res[nres].data = malloc(n ? n : 1);
    memcpy(res[nres].data, p, n);
    res[nres].size = n;
    return (uint32_t)++nres;
}

uint32_t add_res_body(seq *s)
{
    res[nres].kind = RGL_RES_COMMANDS;
    res[nres].data = s->data;
    res[nres].size = s->len;
    return (uint32_t)++nres;
}

void free_res(void)
{
    for (size_t i = 0; i < nres; i++)
        free(res[i].data);
    nres = 0;
}

interp *fresh(void)
{
    scene_reset(&sc);
    diag_clear(&dlog);
    interp *ip = interp_create(&sc, &dlog);
    if (fx_fetch)
        interp_set_resources(ip, fx_fetch, NULL);
    interp_begin_frame(ip);
    return ip;
}

bool fx_run(interp *ip, seq *s)
{
    rgl_error err;
    bool ok = interp_run(ip, s->data, s->len, 0, &err) == RGL_OK;
    seq_free(s);
    return ok;
}

uint64_t count(diag_kind k) { return dlog.e[k].count; }

int keep(void *user, const char *p, size_t n)
{
    (void)user;
    if (nsdl + n >= sizeof sdl)
        return -1;
    memcpy(sdl + nsdl, p, n);
    nsdl += n;
    sdl[nsdl] = 0;
    return 0;
}

bool fx_write_sdl(povwriter *w, const pov_frame_info *info)
{
    povwriter *own = w ? NULL : povwriter_create();
    outbuf ob;
    nsdl = 0;
    sdl[0] = 0;
    if ((!w && !own) || outbuf_init(&ob, 1 << 12, keep, NULL) != 0) {
        povwriter_destroy(own);
        return false;
    }
    bool ok = povwriter_scene(w ? w : own, &ob, &sc, info) == 0;
    ok = outbuf_flush(&ob) == 0 && ok;
    outbuf_finish(&ob);
    if (own)
        povwriter_destroy(own);
    return ok;
}

size_t occurrences(const char *hay, const char *needle)
{
    size_t n = 0;
    for (const char *p = strstr(hay, needle); p; p = strstr(p + 1, needle))
        n++;
    return n;
}
