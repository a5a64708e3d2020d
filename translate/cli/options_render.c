/* options_render.c: the setters of the rendering options (options.def,
 * "Rendering"): parsed into the options' render_settings, which the
 * render driver is handed (render.h).
 */
#include "options.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

bool opt_set_render(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->render.render, ctx, err);
}

bool opt_set_slurm(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->render.slurm, ctx, err);
}

bool opt_set_submit(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->render.submit, ctx, err);
}

bool opt_set_povray(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!*v)
        return opt_fail(err, "%s: empty program name", ctx->option);
    o->render.povray = strchr(v, '/') ? opt_path(o, v, ctx, err) : opt_strdup(o, v, err);
    return o->render.povray != NULL;
}

bool opt_set_engine(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    render_engine e = render_engine_named(v);
    if (e == RENDER_ENGINE_AUTO)
        return opt_fail(err, "%s '%s': expected povray or blender", ctx->option, v);
    o->render.engine = e;
    return true;
}

bool opt_set_blender(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!*v)
        return opt_fail(err, "%s: empty program name", ctx->option);
    o->render.blender = strchr(v, '/') ? opt_path(o, v, ctx, err) : opt_strdup(o, v, err);
    return o->render.blender != NULL;
}

bool opt_set_video(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!*v || v[strlen(v) - 1] == '/')
        return opt_fail(err, "%s '%s': expected a file name", ctx->option, v);
    return (o->render.video = opt_path(o, v, ctx, err)) != NULL;
}

bool opt_set_sshloginfile(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!*v)
        return opt_fail(err, "%s: empty file name", ctx->option);
    return (o->render.sshloginfile = opt_path(o, v, ctx, err)) != NULL;
}

static bool parse_long(const char *v, long lo, long hi, long *out)
{
    char *e;
    if (*v < '0' || *v > '9')
        return false;
    errno = 0;
    long n = strtol(v, &e, 10);
    if (*e || errno || n < lo || n > hi)
        return false;
    *out = n;
    return true;
}

bool opt_set_fps(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    long n;
    if (!parse_long(v, 1, 1000, &n))
        return opt_fail(err, "%s '%s': expected frames per second from 1 to 1000", ctx->option, v);
    o->render.fps = (int)n;
    return true;
}

bool opt_set_samples(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    long n;
    if (!parse_long(v, 1, 1L << 20, &n))
        return opt_fail(err, "%s '%s': expected a number of samples from 1 to 1048576", ctx->option,
                        v);
    o->render.samples = (int)n;
    return true;
}

bool opt_set_task(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!parse_long(v, 0, 1L << 40, &o->render.task))
        return opt_fail(err, "%s '%s': expected an entry number from 0", ctx->option, v);
    return true;
}
