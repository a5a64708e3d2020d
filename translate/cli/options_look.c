/* options_look.c: the setters of the options that change a frame's look
 * (options.def, "Image", "Camera", "Lights"): parsed into the options'
 * look_settings, which the look step applies (look/look.h).
 */
#include "options.h"

#include <errno.h>
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "talloc.h"

/* A number in C notation whatever the locale (the user's locale is on for
 * messages: strtod alone would read "0,5" in de_DE). */
static bool parse_num(const char *s, const char **end, double *out)
{
    static locale_t c_locale;
    if (!c_locale)
        c_locale = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    if (!c_locale)
        return false;
    char *e;
    errno = 0;
    double v = strtod_l(s, &e, c_locale);
    if (e == s || errno == ERANGE || !isfinite(v) || *s == ' ')
        return false;
    *end = e;
    *out = v;
    return true;
}

/* "X,Y,Z" (n numbers separated by commas). */
static bool parse_vec(const char *s, double *v, int n, const char **end)
{
    for (int i = 0; i < n; i++) {
        if (!parse_num(s, &s, &v[i]))
            return false;
        if (i + 1 < n) {
            if (*s != ',')
                return false;
            s++;
        }
    }
    *end = s;
    return true;
}

static bool set_vec(double *v, bool *has, const char *value, const opt_ctx *ctx, opt_err *err)
{
    const char *e;
    if (!parse_vec(value, v, 3, &e) || *e)
        return opt_fail(err, "%s '%s': expected three numbers X,Y,Z", ctx->option, value);
    *has = true;
    return true;
}

static bool set_size(int *v, const char *value, const opt_ctx *ctx, opt_err *err)
{
    char *e;
    long n = strtol(value, &e, 10);
    if (e == value || *e || n < 1 || n > LOOK_MAX_SIZE || value[0] == '-' || value[0] == '+' ||
        value[0] == ' ')
        return opt_fail(err, "%s '%s': expected a size in pixels from 1 to %d", ctx->option,
                        value, LOOK_MAX_SIZE);
    *v = (int)n;
    return true;
}

bool opt_set_width(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return set_size(&o->look.width, v, ctx, err);
}

bool opt_set_height(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return set_size(&o->look.height, v, ctx, err);
}

bool opt_set_camera_location(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return set_vec(o->look.location, &o->look.has_location, v, ctx, err);
}

bool opt_set_camera_look_at(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return set_vec(o->look.look_at, &o->look.has_look_at, v, ctx, err);
}

bool opt_set_camera_up(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!set_vec(o->look.up, &o->look.has_up, v, ctx, err))
        return false;
    const double *u = o->look.up;
    if (u[0] == 0 && u[1] == 0 && u[2] == 0)
        return opt_fail(err, "%s '%s': the up vector cannot be zero", ctx->option, v);
    return true;
}

bool opt_set_camera_fov(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    const char *e;
    double d;
    if (!parse_num(v, &e, &d) || *e || !(d > 0 && d < 180))
        return opt_fail(err, "%s '%s': expected an angle in degrees between 0 and 180",
                        ctx->option, v);
    o->look.fov = d;
    o->look.has_fov = true;
    return true;
}

bool opt_set_camera_orthographic(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->look.orthographic, ctx, err);
}

bool opt_set_override_space(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (strcmp(v, "auto") == 0)
        o->look.eye_space = false;
    else if (strcmp(v, "eye") == 0)
        o->look.eye_space = true;
    else
        return opt_fail(err, "%s '%s': expected auto or eye", ctx->option, v);
    return true;
}

bool opt_set_no_gl_lights(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->look.no_gl_lights, ctx, err);
}

bool opt_set_antialias(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->look.options.antialias, ctx, err);
}

bool opt_set_radiosity(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->look.options.radiosity, ctx, err);
}

bool opt_set_quality(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    char *e;
    long n = strtol(v, &e, 10);
    if (e == v || *e || n < 0 || n > 11 || v[0] == ' ' || v[0] == '+')
        return opt_fail(err, "%s '%s': expected a POV-Ray quality from 0 to 11", ctx->option, v);
    o->look.options.quality = n == 0 ? -1 : (int)n; /* -1: Quality=0 asked for */
    return true;
}

bool opt_set_preview(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    bool on;
    if (!opt_bool(v, &on, ctx, err))
        return false;
    o->preview = on;
    if (on) { /* quality 4: no reflections, media, image maps; no shadows here */
        o->look.options.quality = 4;
        o->look.options.no_shadows = true;
    }
    return true;
}

bool opt_set_include(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    look_settings *l = &o->look;
    const char *path = opt_path(o, v, ctx, err);
    if (!path)
        return false;
    struct stat st;
    if (stat(path, &st) != 0)
        return opt_fail(err, "%s '%s': %s", ctx->option, path, strerror(errno));
    if (!S_ISREG(st.st_mode))
        return opt_fail(err, "%s '%s': not a regular file", ctx->option, path);
    if (tr_grow((void **)&l->includes, &l->cap_includes, l->nincludes + 1, sizeof *l->includes))
        return opt_fail(err, "out of memory");
    l->includes[l->nincludes++] = path;
    return true;
}

/* KIND key=value ...: see the man page. */
bool opt_set_light(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    static const char *const kinds[] = {"point", "parallel", "spot", "area"};
    look_light L;
    memset(&L, 0, sizeof L);
    L.color[0] = L.color[1] = L.color[2] = 1;
    L.radius = 30;
    L.falloff = 45;
    L.size[0] = L.size[1] = 1;
    L.samples[0] = L.samples[1] = 5;
    const char *p = v;
    while (*p == ' ')
        p++;
    size_t kl = strcspn(p, " ");
    int kind = -1;
    for (int k = 0; k < 4; k++)
        if (strlen(kinds[k]) == kl && strncmp(p, kinds[k], kl) == 0)
            kind = k;
    if (kind < 0)
        return opt_fail(err, "%s '%s': expected point, parallel, spot or area first", ctx->option,
                        v);
    L.kind = (look_light_kind)kind;
    p += kl;
    bool has_at = false;
    while (*p) {
        while (*p == ' ')
            p++;
        if (!*p)
            break;
        const char *key = p, *e;
        size_t n = strcspn(p, "= ");
        p += n;
        if (*p != '=')
            return opt_fail(err, "%s '%s': expected key=value at '%.*s'", ctx->option, v,
                            (int)n, key);
        p++;
        bool ok;
        double d[2];
#define KEY(s) (n == strlen(s) && strncmp(key, s, n) == 0)
        if (KEY("at"))
            ok = parse_vec(p, L.at, 3, &e), has_at = true;
        else if (KEY("to"))
            ok = parse_vec(p, L.to, 3, &e);
        else if (KEY("color") || KEY("colour"))
            ok = parse_vec(p, L.color, 3, &e) && L.color[0] >= 0 && L.color[1] >= 0 &&
                 L.color[2] >= 0;
        else if (KEY("radius") && L.kind == LOOK_LIGHT_SPOT)
            ok = parse_num(p, &e, &L.radius) && L.radius >= 0 && L.radius <= 90;
        else if (KEY("falloff") && L.kind == LOOK_LIGHT_SPOT)
            ok = parse_num(p, &e, &L.falloff) && L.falloff >= 0 && L.falloff <= 90;
        else if (KEY("size") && L.kind == LOOK_LIGHT_AREA)
            ok = parse_vec(p, L.size, 2, &e) && L.size[0] > 0 && L.size[1] > 0;
        else if (KEY("samples") && L.kind == LOOK_LIGHT_AREA) {
            ok = parse_vec(p, d, 2, &e) && d[0] >= 1 && d[0] <= 64 && d[1] >= 1 && d[1] <= 64 &&
                 d[0] == floor(d[0]) && d[1] == floor(d[1]);
            if (ok) {
                L.samples[0] = (int)d[0];
                L.samples[1] = (int)d[1];
            }
        } else
            return opt_fail(err, "%s '%s': no key '%.*s' for a %s light", ctx->option, v,
                            (int)n, key, kinds[kind]);
#undef KEY
        if (!ok || (*e && *e != ' '))
            return opt_fail(err, "%s '%s': bad value for '%.*s'", ctx->option, v, (int)n, key);
        p = e;
    }
    if (!has_at)
        return opt_fail(err, "%s '%s': the light needs at=X,Y,Z", ctx->option, v);
    if (L.kind == LOOK_LIGHT_SPOT && L.falloff < L.radius)
        return opt_fail(err, "%s '%s': falloff must not be less than radius", ctx->option, v);
    look_settings *l = &o->look;
    if (tr_grow((void **)&l->lights, &l->cap_lights, l->nlights + 1, sizeof L) != 0)
        return opt_fail(err, "out of memory");
    l->lights[l->nlights++] = L;
    return true;
}

