/* povwrite_clip.c: user clip planes (interp_clip.c) as POV-Ray clipped_by
 * planes. GL keeps eye-space points with a x + b y + c z + d >= 0; a
 * POV-Ray plane{n, e} holds the points with n . p <= e, so each plane is
 * written as plane{-(a, b, c), d} (unit normals: interp_clip.c normalises
 * them). Written after the object's matrix, so in eye space: exact. */
#include "povwrite_clip.h"

#include <math.h>

#include "mat4.h"

void povwrite_clip(outbuf *ob, const scene *s, const scene_look *look)
{
    uint32_t n;
    const double (*p)[4] = scene_clip_set(s, look->clip, &n);
    if (!p)
        return;
    outbuf_puts(ob, "clipped_by{");
    for (uint32_t i = 0; i < n; i++) {
        double a = p[i][0], b = p[i][1], c = p[i][2], d = p[i][3];
        if (!isfinite(a) || !isfinite(b) || !isfinite(c) || !isfinite(d))
            continue;
        if (a == 0 && b == 0 && c == 0) {
            if (d >= 0)
                continue; /* keeps everything */
            a = 0, b = 0, c = -1, d = -1e30; /* keeps nothing */
        }
        outbuf_puts(ob, "plane{<");
        outbuf_f32(ob, (float)-a);
        outbuf_putc(ob, ',');
        outbuf_f32(ob, (float)-b);
        outbuf_putc(ob, ',');
        outbuf_f32(ob, (float)-c);
        outbuf_puts(ob, ">,");
        outbuf_f32(ob, (float)d);
        outbuf_putc(ob, '}');
    }
    outbuf_puts(ob, "}\n");
}

static void put_plane(outbuf *ob, const double n[3], double d)
{
    outbuf_puts(ob, "plane{<");
    outbuf_f32(ob, (float)n[0]);
    outbuf_putc(ob, ',');
    outbuf_f32(ob, (float)n[1]);
    outbuf_putc(ob, ',');
    outbuf_f32(ob, (float)n[2]);
    outbuf_puts(ob, ">,");
    outbuf_f32(ob, (float)d);
    outbuf_putc(ob, '}');
}

/* The cone of rays through triangle t: three planes, each holding the
 * rays along one edge (through the eye in perspective, along the view in
 * orthographic), the third corner inside (POV-Ray keeps n . p <= d). */
static bool put_cone(outbuf *ob, const scene_camera *cam, const double *t)
{
    bool persp = cam->kind != SCENE_CAMERA_ORTHOGRAPHIC;
    double n[3][3], d[3];
    for (int e = 0; e < 3; e++) {
        const double *a = t + 3 * e, *b = t + 3 * ((e + 1) % 3), *c = t + 3 * ((e + 2) % 3);
        double ab[3], other[3];
        for (int k = 0; k < 3; k++) {
            ab[k] = b[k] - a[k];
            other[k] = persp ? a[k] - cam->location[k] : cam->direction[k];
        }
        cross3(ab, other, n[e]);
        double len = len3(n[e]);
        if (!(len > 1e-12) || !isfinite(len))
            return false; /* edge-on: covers no pixel centre */
        for (int k = 0; k < 3; k++)
            n[e][k] /= len;
        d[e] = dot3(n[e], a);
        if (dot3(n[e], c) > d[e]) {
            for (int k = 0; k < 3; k++)
                n[e][k] = -n[e][k];
            d[e] = -d[e];
        }
    }
    outbuf_puts(ob, "intersection{");
    for (int e = 0; e < 3; e++)
        put_plane(ob, n[e], d[e]);
    outbuf_putc(ob, '}');
    return true;
}

void povwrite_stencil(outbuf *ob, const scene *s, const scene_look *look)
{
    if (!look->stencil_n || (size_t)look->stencil_first + look->stencil_n > s->nstencil)
        return;
    outbuf_puts(ob, "clipped_by{union{");
    bool any = false;
    for (uint32_t i = 0; i < look->stencil_n; i++) {
        const double *t = s->stencil_tris[look->stencil_first + i];
        bool ok = true;
        for (int k = 0; k < 9; k++)
            ok = ok && isfinite(t[k]);
        if (ok && put_cone(ob, &s->camera, t)) {
            outbuf_putc(ob, '\n');
            any = true;
        }
    }
    if (!any) /* no pixel: the region is empty */
        outbuf_puts(ob, "plane{<0,0,1>,-1e30}");
    if (look->stencil_out)
        outbuf_puts(ob, " inverse");
    outbuf_puts(ob, "}}\n");
}
