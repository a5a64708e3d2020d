/* scene_clip.c: the scene's user clip plane sets and polygon stipple masks
 * (scene.h), which meshes and solids refer to from their look, as name
 * stacks are referred to. */
#include <string.h>

#include "scene.h"
#include "talloc.h"

uint32_t scene_clip_index(scene *s, const double (*planes)[4], uint32_t n)
{
    if (n == 0 || n > 64 || s->failed)
        return 0;
    if (s->clips_last) {
        double (*l)[4] = s->clips + s->clips_last;
        if (l[-1][0] == n && memcmp(l, planes, n * sizeof *planes) == 0)
            return (uint32_t)s->clips_last;
    }
    if (s->nclips + n + 1 > UINT32_MAX / 2 ||
        tr_grow((void **)&s->clips, &s->cap_clips, s->nclips + n + 1, sizeof *s->clips) != 0) {
        s->failed = true;
        return 0;
    }
    s->clips[s->nclips][0] = n;
    s->clips[s->nclips][1] = s->clips[s->nclips][2] = s->clips[s->nclips][3] = 0;
    memcpy(s->clips + s->nclips + 1, planes, n * sizeof *planes);
    s->clips_last = s->nclips + 1;
    s->nclips += n + 1;
    return (uint32_t)s->clips_last;
}

const double (*scene_clip_set(const scene *s, uint32_t id, uint32_t *n))[4]
{
    *n = 0;
    if (id == 0 || id > s->nclips)
        return NULL;
    double c = s->clips[id - 1][0];
    if (!(c >= 1 && c <= (double)(s->nclips - id)))
        return NULL;
    *n = (uint32_t)c;
    return (const double(*)[4])(s->clips + id);
}

uint32_t scene_pstipple_index(scene *s, const uint8_t mask[128])
{
    if (s->failed)
        return 0;
    if (s->npstipples && memcmp(s->pstipples[s->npstipples - 1], mask, 128) == 0)
        return (uint32_t)s->npstipples;
    if (s->npstipples + 1 > UINT32_MAX / 2 ||
        tr_grow((void **)&s->pstipples, &s->cap_pstipples, s->npstipples + 1, sizeof *s->pstipples) !=
            0) {
        s->failed = true;
        return 0;
    }
    memcpy(s->pstipples[s->npstipples++], mask, 128);
    return (uint32_t)s->npstipples;
}

const uint8_t *scene_pstipple_mask(const scene *s, uint32_t id)
{
    return id == 0 || id > s->npstipples ? NULL : s->pstipples[id - 1];
}
