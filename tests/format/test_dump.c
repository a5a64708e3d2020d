/* test_dump.c: rgl_cmd_format's text, exactly.
 *
 * Enum names by hint, hex for unknown enums, handles as #id, blobs as sizes,
 * strings escaped, floats with the fewest digits that read back (checked by
 * parsing every printed float of many random ones), NaN and infinities, the
 * snprintf-like return value and truncation, and the same text under a
 * locale whose decimal separator is a comma (de_DE, built with localedef
 * into a temporary directory when the system lacks it).
 */
#include <locale.h>
#include <unistd.h>

#include "testutil.h"

static char line[16384];

static void expect(const rgl_cmd *cmd, const char *want)
{
    size_t n = rgl_cmd_format(cmd, line, sizeof line);
    CHECKF(n == strlen(want) && strcmp(line, want) == 0, "got  %s\n    want %s", line, want);
}

static void set_floats(rgl_cmd *cmd, uint32_t arg, const double *v, uint32_t n)
{
    cmd->arg[arg].count = n;
    for (uint32_t k = 0; k < n; k++)
        ((double *)cmd->arg[arg].array)[k] = v[k];
}

static void fixed_lines(void)
{
    static rgl_cmd c;
    static const double pos[] = {1, 2, 3, 0};

    rgl_cmd_init(&c, RGL_OP_Lightfv);
    c.arg[0].v.u = 0x4000;
    c.arg[1].v.u = 0x1203;
    set_floats(&c, 2, pos, 4);
    expect(&c, "glLightfv(light=GL_LIGHT0, pname=GL_POSITION, params=[1, 2, 3, 0])");

    rgl_cmd_init(&c, RGL_OP_NewList);
    c.arg[0].v.u = 1;
    c.arg[1].v.u = 0x1300;
    c.arg[2].v.u = 7;
    expect(&c, "glNewList(list=1, mode=GL_COMPILE, body=#7)");

    rgl_cmd_init(&c, RGL_OP_DrawElements);
    c.arg[0].v.u = 4;
    c.arg[1].v.i = 6;
    c.arg[2].v.u = 0x1403;
    c.arg[3].count = 12;
    c.arg[3].bytes = (const uint8_t *)"abcdefghijkl";
    expect(&c, "glDrawElements(mode=GL_TRIANGLES, count=6, type=GL_UNSIGNED_SHORT, "
               "indices=<12 bytes>)");

    rgl_cmd_init(&c, RGL_OP_Begin);
    c.arg[0].v.u = 0;
    expect(&c, "glBegin(mode=GL_POINTS)");
    rgl_cmd_init(&c, RGL_OP_BlendFunc);
    c.arg[0].v.u = 1;
    c.arg[1].v.u = 0;
    expect(&c, "glBlendFunc(sfactor=GL_ONE, dfactor=GL_ZERO)");
    rgl_cmd_init(&c, RGL_OP_Enable);
    c.arg[0].v.u = 0;
    expect(&c, "glEnable(cap=0x0)");
    c.arg[0].v.u = 0x0B50;
    expect(&c, "glEnable(cap=GL_LIGHTING)");
    c.arg[0].v.u = 0xabcdef;
    expect(&c, "glEnable(cap=0xabcdef)");
    rgl_cmd_init(&c, RGL_OP_Clear);
    c.arg[0].v.u = 0x4100;
    expect(&c, "glClear(mask=0x4100)");
    rgl_cmd_init(&c, RGL_OP_ColorMask);
    c.arg[0].v.u = 1;
    c.arg[2].v.u = 2;
    expect(&c, "glColorMask(red=GL_TRUE, green=GL_FALSE, blue=2, alpha=GL_FALSE)");
    rgl_cmd_init(&c, RGL_OP_End);
    expect(&c, "glEnd()");
    rgl_cmd_init(&c, RGL_OP_Vertex3i);
    c.arg[0].v.i = INT32_MIN;
    c.arg[1].v.i = -1;
    c.arg[2].v.i = INT32_MAX;
    expect(&c, "glVertex3i(x=-2147483648, y=-1, z=2147483647)");
    rgl_cmd_init(&c, RGL_OP_Color4ubv);
    set_floats(&c, 0, (const double[]){255, 0, 128, 1}, 4);
    expect(&c, "glColor4ubv(v=[255, 0, 128, 1])");
    rgl_cmd_init(&c, RGL_OP_QuadricDrawStyle);
    c.arg[0].v.u = 3;
    c.arg[1].v.u = 100012;
    expect(&c, "gluQuadricDrawStyle(quad=#3, draw=GLU_FILL)");
    rgl_cmd_init(&c, RGL_OP_Matrix);
    c.arg[0].v.u = 0x1700;
    for (int k = 0; k < 16; k++)
        ((double *)c.arg[1].array)[k] = k % 5 == 0;
    expect(&c, "@Matrix(mode=GL_MODELVIEW, m=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])");

    rgl_cmd_init(&c, RGL_OP_FrameBegin);
    c.arg[0].bytes = (const uint8_t *)"a\"b\\c\n\t\x01\xc3\xa9";
    c.arg[0].count = 10;
    c.arg[1].v.f = 45;
    c.arg[4].v.f = -0.0;
    expect(&c, "rayglFrameBegin(file=\"a\\\"b\\\\c\\n\\t\\x01\\xc3\\xa9\", locx=45, locy=0, "
               "locz=0, lookx=-0, looky=0, lookz=0, lightx=0, lighty=0, lightz=0)");
    printf("  fixed lines: enums by hint, hex, handles, blobs, booleans, strings escaped\n");
}

/* Significant digits of a printed number: from the first non-zero digit to
 * the last, before any exponent. */
static int significant_digits(const char *s)
{
    int n = 0, last = 0;
    bool lead = true;
    for (; *s && *s != 'e' && *s != ')'; s++) {
        if (*s < '0' || *s > '9')
            continue;
        if (lead && *s == '0')
            continue;
        lead = false;
        n++;
        if (*s != '0')
            last = n;
    }
    return last;
}

static void float_lines(void)
{
    static rgl_cmd c;
    static const struct {
        uint32_t bits;
        const char *text;
    } fl[] = {
        {0x3dcccccdu, "0.1"},        {0x3eaaaaabu, "0.33333334"}, {0x00000001u, "1e-45"},
        {0x80000000u, "-0"},          {0x7f800000u, "inf"},         {0xff800000u, "-inf"},
        {0x7fc00000u, "nan"},         {0x7fa00001u, "nan(0x7fa00001)"},
        {0x7f7fffffu, "3.4028235e+38"}, {0x4b800000u, "16777216"},  {0x3f000000u, "0.5"},
        {0xc0c00000u, "-6"},          {0x49742400u, "1000000"}, {0x42c80000u, "100"}, {0x4e6e6b28u, "1e+09"},
        {0x4cbebc20u, "100000000"}, {0x3a83126fu, "0.001"}, {0x38d1b717u, "0.0001"}, {0x4e5e84f0u, "933313540"},
    };
    rgl_cmd_init(&c, RGL_OP_PointSize);
    for (size_t i = 0; i < sizeof fl / sizeof fl[0]; i++) {
        char want[64];
        c.arg[0].v.f = f32_as_double(fl[i].bits);
        snprintf(want, sizeof want, "glPointSize(size=%s)", fl[i].text);
        expect(&c, want);
    }
    rgl_cmd_init(&c, RGL_OP_ClearDepth);
    c.arg[0].v.f = 0.1;
    expect(&c, "glClearDepth(depth=0.1)");
    c.arg[0].v.f = 1.0 / 3;
    expect(&c, "glClearDepth(depth=0.3333333333333333)");
    c.arg[0].v.f = 5e-324;
    expect(&c, "glClearDepth(depth=5e-324)");

    /* Random floats and doubles: the printed text parses back exactly. */
    rng r = {99};
    unsigned long checked = 0;
    for (int i = 0; i < 20000; i++) {
        uint32_t bits = (uint32_t)rng_next(&r);
        float f = rgl_bits_f32(bits);
        double d = rgl_bits_f64(rng_next(&r));
        if (isnan(f) || isinf(f) || isnan(d) || isinf(d))
            continue;
        rgl_cmd_init(&c, RGL_OP_PointSize);
        c.arg[0].v.f = f;
        rgl_cmd_format(&c, line, sizeof line);
        const char *num = strchr(line, '=') + 1;
        CHECKF(strtof(num, NULL) == f, "%s does not read back as 0x%08lx", line,
               (unsigned long)bits);
        /* and no shorter: one significant digit less does not read back */
        int digits = significant_digits(num);
        if (digits > 1) {
            char shorter[512];
            snprintf(shorter, sizeof shorter, "%.*g", digits - 1, (double)f);
            CHECKF(strtof(shorter, NULL) != f, "%s: %s is shorter", line, shorter);
        }
        rgl_cmd_init(&c, RGL_OP_ClearDepth);
        c.arg[0].v.f = d;
        rgl_cmd_format(&c, line, sizeof line);
        num = strchr(line, '=') + 1;
        CHECKF(strtod(num, NULL) == d, "%s does not read back", line);
        digits = significant_digits(num);
        if (digits > 1) {
            char shorter[512];
            snprintf(shorter, sizeof shorter, "%.*g", digits - 1, d);
            CHECKF(strtod(shorter, NULL) != d, "%s: %s is shorter", line, shorter);
        }
        checked++;
    }
    printf("  floats: shortest text for fixed cases, %lu random floats and doubles read back\n",
           checked);
}

static void truncation(void)
{
    static rgl_cmd c;
    char small[8];
    rgl_cmd_init(&c, RGL_OP_Vertex3f);
    size_t n = rgl_cmd_format(&c, small, sizeof small);
    CHECK(n == strlen("glVertex3f(x=0, y=0, z=0)"));
    CHECK(strcmp(small, "glVerte") == 0);
    CHECK(rgl_cmd_format(&c, NULL, 0) == n);
    CHECK(rgl_cmd_format(&c, small, 1) == n && small[0] == '\0');
    printf("  return value like snprintf; output truncated and terminated\n");
}

/* The same lines under a locale with a decimal comma. */
static void locale_independence(void)
{
    static rgl_cmd c;
    char dir[] = "/tmp/rgl-locale-XXXXXX", cmdline[256];
    bool made = false;

    if (!setlocale(LC_ALL, "de_DE.UTF-8") && mkdtemp(dir)) {
        made = true;
        snprintf(cmdline, sizeof cmdline,
                 "localedef -i de_DE -f UTF-8 %s/de_DE.UTF-8 >/dev/null 2>&1", dir);
        if (system(cmdline) == 0) {
            setenv("LOCPATH", dir, 1);
            setlocale(LC_ALL, "de_DE.UTF-8");
        }
    }
    const struct lconv *lc = localeconv();
    if (strcmp(lc->decimal_point, ",") != 0) {
        printf("  locale: no de_DE locale could be had here; decimal-comma check not run\n");
    } else {
        char probe[16];
        snprintf(probe, sizeof probe, "%.1f", 0.5);
        CHECK(strcmp(probe, "0,5") == 0); /* the locale is really in force */
        rgl_cmd_init(&c, RGL_OP_Rotatef);
        c.arg[0].v.f = 0.5;
        c.arg[1].v.f = f32_as_double(0x3dcccccdu);
        c.arg[2].v.f = -1234.5;
        c.arg[3].v.f = 1e-7f;
        expect(&c, "glRotatef(angle=0.5, x=0.1, y=-1234.5, z=1e-07)");
        rgl_cmd_init(&c, RGL_OP_ClearDepth);
        c.arg[0].v.f = 0.75;
        expect(&c, "glClearDepth(depth=0.75)");
        printf("  locale: de_DE (decimal comma) in force, text unchanged\n");
    }
    setlocale(LC_ALL, "C");
    if (made) {
        snprintf(cmdline, sizeof cmdline, "rm -rf %s", dir);
        if (system(cmdline) != 0)
            fprintf(stderr, "  (could not remove %s)\n", dir);
    }
}

int main(void)
{
    fixed_lines();
    float_lines();
    truncation();
    locale_independence();
    return test_summary("test_dump");
}
