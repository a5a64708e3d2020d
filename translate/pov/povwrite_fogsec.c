/* povwrite_fogsec.c: the fog layer of a draw fogged by one fog coordinate
 * (interp_fogsec.c): GL shows f C + (1 - f) fog colour with the same f
 * over the whole surface, so the layer is the fog colour with a constant
 * transmit f, over the lit or textured surface POV-Ray computes. Other
 * fogged draws take povlight_fog_declare's eye-distance layer. */
#include "povwrite_fogsec.h"

#include <math.h>

static void put_num(outbuf *ob, double v)
{
    float f = (float)v;
    outbuf_f32(ob, isfinite(f) ? f : 0.0f);
}

void povfog_declare(const povlight *pl, outbuf *ob, const char *name, const mat4 *to_eye,
                    const scene_look *look)
{
    if (!look->fog_fixed) {
        povlight_fog_declare(pl, ob, name, to_eye, pl->s->fog.distance);
        return;
    }
    const scene_fog *fg = &pl->s->fog;
    double f = look->fog_f > 0 ? (look->fog_f < 1 ? look->fog_f : 1) : 0;
    outbuf_puts(ob, "#declare ");
    outbuf_puts(ob, name);
    outbuf_puts(ob, "=texture{pigment{rgbt<");
    for (int k = 0; k < 3; k++) {
        put_num(ob, fg->color[k]);
        outbuf_putc(ob, ',');
    }
    put_num(ob, f);
    outbuf_puts(ob, ">}finish{ambient 0 diffuse 0 emission 1}}\n");
}
