/* povwrite_clip.c: user clip planes (interp_clip.c) as POV-Ray clipped_by
 * planes. GL keeps eye-space points with a x + b y + c z + d >= 0; a
 * POV-Ray plane{n, e} holds the points with n . p <= e, so each plane is
 * written as plane{-(a, b, c), d} (unit normals: interp_clip.c normalises
 * them). Written after the object's matrix, so in eye space: exact. */
#include "povwrite_clip.h"

#include <math.h>

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
