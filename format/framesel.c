/* framesel.c: the frame-list parser (framesel.h). */
#include "framesel.h"

bool rgl_parse_u64(const char *s, const char **end, uint64_t *out)
{
    uint64_t v = 0;
    if (*s < '0' || *s > '9')
        return false;
    for (; *s >= '0' && *s <= '9'; s++) {
        if (v > (UINT64_MAX - 9) / 10)
            return false;
        v = v * 10 + (uint64_t)(*s - '0');
    }
    *end = s;
    *out = v;
    return true;
}

rgl_framesel_status rgl_framesel_next(const char **pp, rgl_frame_range *r)
{
    const char *p = *pp, *e;
    r->first = r->last = 0;
    r->step = 1;
    if (!rgl_parse_u64(p, &e, &r->first))
        return RGL_FRAMESEL_NUMBER;
    r->last = r->first;
    p = e;
    if (*p == '-') {
        p++;
        if (*p == ',' || *p == ':' || *p == '\0') {
            r->last = UINT64_MAX;
        } else if (!rgl_parse_u64(p, &e, &r->last)) {
            *pp = p;
            return RGL_FRAMESEL_NUMBER;
        } else {
            p = e;
        }
        if (r->last < r->first)
            return RGL_FRAMESEL_BACKWARDS;
    }
    if (*p == ':') {
        p++;
        if (!rgl_parse_u64(p, &e, &r->step) || r->step == 0) {
            *pp = p;
            return RGL_FRAMESEL_STEP;
        }
        p = e;
    }
    if (*p == ',') {
        p++;
    } else if (*p) {
        *pp = p;
        return RGL_FRAMESEL_UNEXPECTED;
    }
    *pp = p;
    return RGL_FRAMESEL_OK;
}
