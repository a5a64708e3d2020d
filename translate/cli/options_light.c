/* options_light.c: the setters of the ray-tracing options (options.def,
 * "Ray tracing"): what the writers add to the OpenGL look, as the look
 * step puts it into the scene (scene.h, scene_options; docs/mapping.md
 * "What ray tracing adds").
 */
#include "options.h"

/* A decimal number from 0 to 1 ("0.25", ".5", "1"), read without the
 * locale (a de_DE locale must not change what "0.5" means). */
static bool parse_unit(const char *s, double *out)
{
    double v = 0, scale = 1;
    bool digits = false, dot = false;
    for (; *s; s++) {
        if (*s >= '0' && *s <= '9') {
            digits = true;
            if (dot) {
                scale /= 10;
                v += (*s - '0') * scale;
            } else {
                v = v * 10 + (*s - '0');
                if (v > 1)
                    return false;
            }
        } else if (*s == '.' && !dot) {
            dot = true;
        } else {
            return false;
        }
    }
    if (!digits || v > 1)
        return false;
    *out = v;
    return true;
}

bool opt_set_no_shadows(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->look.options.no_shadows, ctx, err);
}

bool opt_set_reflection(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    double r;
    if (!parse_unit(v, &r))
        return opt_fail(err, "%s '%s': expected a number from 0 to 1", ctx->option, v);
    o->look.options.reflection = (float)r;
    return true;
}

bool opt_set_area_lights(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    int n = 0;
    const char *p = v;
    for (; *p >= '0' && *p <= '9' && n <= 16; p++)
        n = n * 10 + (*p - '0');
    if (p == v || *p || n < 2 || n > 16)
        return opt_fail(err, "%s '%s': expected a number from 2 to 16", ctx->option, v);
    o->look.options.area_lights = n;
    return true;
}

bool opt_set_vertex_lighting(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->vertex_lighting, ctx, err);
}
