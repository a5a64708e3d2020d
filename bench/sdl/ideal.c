/* ideal.c: the hand-written ideal SDL of bench_translate's torus, the
 * yardstick of what POV-Ray must spend to parse that geometry (issue 16).
 *
 *   ideal --tris N [--one-colour] OUT.pov
 *
 * Written apart from the project's writer, from the same formulas as
 * bench/translate/bench_translate.c (torus_vertex, build_frame: 256 sides,
 * N / 512 rings, phase 0, the same modelview): one mesh2 with each grid
 * vertex once, its normal parallel (taken by face_indices), and either one
 * texture (one colour) or the vertex colours as one image of a texel per
 * vertex (OUT.ppm beside OUT.pov), uv per vertex, also taken by
 * face_indices. The camera and light are those raygl2pov writes for the
 * frame, so only the mesh differs. Numbers are the shortest text that
 * reads back as the same float, as the project's writer writes them.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The shortest %.Ng (N 6..9) that reads back as the float v. */
static void put_num(FILE *f, double v)
{
    float x = (float)v;
    char s[32];
    for (int p = 6; p <= 9; p++) {
        snprintf(s, sizeof s, "%.*g", p, (double)x);
        if (strtof(s, NULL) == x)
            break;
    }
    fputs(s, f);
}

static void put_vec(FILE *f, const double v[3])
{
    fputs(",\n<", f);
    for (int k = 0; k < 3; k++) {
        if (k)
            fputc(',', f);
        put_num(f, v[k]);
    }
    fputc('>', f);
}

int main(int argc, char **argv)
{
    long tris = 262144;
    int one = 0;
    const char *out = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--tris") == 0 && i + 1 < argc)
            tris = atol(argv[++i]);
        else if (strcmp(argv[i], "--one-colour") == 0)
            one = 1;
        else if (!out && argv[i][0] != '-')
            out = argv[i];
        else
            out = NULL, i = argc;
    }
    if (!out || tris < 1) {
        fprintf(stderr, "usage: ideal --tris N [--one-colour] OUT.pov\n");
        return 2;
    }
    int sides = 256, rings = (int)(tris / (2 * sides));
    if (rings < 3)
        rings = 3;
    int nu = sides + 1, nv = rings + 1; /* the strips' grid, seams kept as GL sent them */
    long nverts = (long)nu * nv;
    FILE *f = fopen(out, "w");
    if (!f) {
        perror(out);
        return 1;
    }
    char ppm[4096], ppm_name[4096];
    snprintf(ppm, sizeof ppm, "%.*s.ppm", (int)strlen(out) - 4, out);
    const char *slash = strrchr(ppm, '/');
    snprintf(ppm_name, sizeof ppm_name, "%s", slash ? slash + 1 : ppm);

    /* The frame's camera and light (gluPerspective(45, 4/3), the light at
     * GL_LIGHT0's default direction, +z in eye space). */
    double fy = tan(22.5 * M_PI / 180);
    fprintf(f, "#version 3.7;\nglobal_settings{assumed_gamma 2.2}\n"
               "camera{perspective location<0,0,0> right<%.8g,0,0> up<0,%.8g,0> "
               "direction<0,0,-1>}\nbackground{rgb<0.1,0.1,0.2>}\n",
            2 * fy * 640 / 480, 2 * fy);
    fputs("mesh2{\nvertex_vectors{", f);
    fprintf(f, "%ld", nverts);
    for (int i = 0; i < nv; i++)
        for (int j = 0; j < nu; j++) {
            double u = 2 * M_PI * i / rings, v = 2 * M_PI * j / sides;
            double p[3] = {(2 + 0.7 * cos(v)) * cos(u), (2 + 0.7 * cos(v)) * sin(u), 0.7 * sin(v)};
            put_vec(f, p);
        }
    fprintf(f, "}\nnormal_vectors{%ld", nverts);
    for (int i = 0; i < nv; i++)
        for (int j = 0; j < nu; j++) {
            double u = 2 * M_PI * i / rings, v = 2 * M_PI * j / sides;
            double n[3] = {cos(u) * cos(v), sin(u) * cos(v), sin(v)};
            put_vec(f, n);
        }
    fputs("}\n", f);
    if (!one) {
        /* A texel per vertex: (j, i) at column j, row nv-1-i (image rows
         * run top down, v up); uv at the texel's centre. */
        fprintf(f, "uv_vectors{%ld", nverts);
        for (int i = 0; i < nv; i++)
            for (int j = 0; j < nu; j++) {
                fputs(",\n<", f);
                put_num(f, (j + 0.5) / nu);
                fputc(',', f);
                put_num(f, (i + 0.5) / nv);
                fputc('>', f);
            }
        fputs("}\n", f);
        FILE *img = fopen(ppm, "wb");
        if (!img) {
            perror(ppm);
            return 1;
        }
        fprintf(img, "P6\n%d %d\n255\n", nu, nv);
        for (int i = nv - 1; i >= 0; i--)
            for (int j = 0; j < nu; j++) {
                double u = 2 * M_PI * i / rings, v = 2 * M_PI * j / sides;
                double c[3] = {0.5 + 0.5 * cos(u), 0.5 + 0.5 * sin(v), 0.5 + 0.5 * cos(u + v)};
                for (int k = 0; k < 3; k++)
                    fputc((int)lround(c[k] * 255), img);
            }
        if (fclose(img) != 0) {
            perror(ppm);
            return 1;
        }
    }
    long nfaces = 2L * rings * sides;
    fprintf(f, "face_indices{%ld", nfaces);
    for (int i = 0; i < rings; i++)
        for (int j = 0; j < sides; j++) {
            long a = (long)i * nu + j, b = a + 1, c = a + nu, d = c + 1;
            fprintf(f, ",\n<%ld,%ld,%ld>,\n<%ld,%ld,%ld>", a, c, b, b, c, d);
        }
    fputs("}\n", f);
    if (one)
        fputs("texture{pigment{rgb<0.8,0.6,0.2>}", f);
    else
        fprintf(f, "texture{uv_mapping pigment{image_map{ppm \"%s\" gamma 2.2 interpolate 2}}",
                ppm_name);
    fputs("finish{diffuse 1 ambient rgb<0.2,0.2,0.2> emission 0}}\n", f);
    /* glTranslatef(0,0,-8) glRotatef(30, 1,0.3,0), as bench_translate's frame 0. */
    double ax = 1, ay = 0.3, az = 0, l = sqrt(ax * ax + ay * ay + az * az);
    ax /= l, ay /= l, az /= l;
    double a = 30 * M_PI / 180, c = cos(a), s = sin(a), t = 1 - c;
    double r[3][3] = {{t * ax * ax + c, t * ax * ay - s * az, t * ax * az + s * ay},
                      {t * ax * ay + s * az, t * ay * ay + c, t * ay * az - s * ax},
                      {t * ax * az - s * ay, t * ay * az + s * ax, t * az * az + c}};
    /* POV-Ray's matrix is row-vector: its rows are the columns of GL's. */
    fputs("matrix<", f);
    for (int col = 0; col < 3; col++)
        for (int row = 0; row < 3; row++) {
            put_num(f, r[row][col]);
            fputc(',', f);
        }
    fputs("0,0,-8>\n}\n", f);
    fputs("light_source{<0,0,1> rgb<1,1,1> parallel point_at<0,0,0>}\n", f);
    if (fclose(f) != 0) {
        perror(out);
        return 1;
    }
    return 0;
}
