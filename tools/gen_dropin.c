/* gen_dropin.c: writes include/raygl/gl.h, the drop-in header, from the
 * command table: one `#define glX rayglX` per GL, GLU and GLUT row; the
 * calls not recorded come from raygl/unrecorded.h, which it includes. Run
 * by the build; the output is never edited by hand. */
#include <stdio.h>

#include "cmdtable.h"

#define RGL_DROPIN_GL(name) "gl" #name, "raygl" #name
#define RGL_DROPIN_GLU(name) "glu" #name, "raygl" "u" #name
#define RGL_DROPIN_GLUT(name) "glut" #name, "raygl" "ut" #name
#define RGL_DROPIN_RAY(name) NULL, NULL
#define RGL_DROPIN_REC(name) NULL, NULL

static const char *const pairs[][2] = {
#define RGL_CMD(op, api, gen, name, handler, ...) {RGL_DROPIN_##api(name)},
#include "commands.def"
#undef RGL_CMD
};

int main(void)
{
    puts("/* raygl/gl.h: drop-in recording. Include it after the GL, GLU and GLUT");
    puts(" * headers (or pass -include raygl/gl.h) and every supported gl*, glu*");
    puts(" * and glut* call becomes its raygl twin. Generated from commands.def. */");
    puts("#ifndef RAYGL_GL_H");
    puts("#define RAYGL_GL_H");
    puts("#include <raygl.h>");
    /* The twins of the calls not recorded (tools/gen_unrecorded.py), with
     * their macros. */
    puts("#include \"unrecorded.h\"");
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++)
        if (pairs[i][0])
            printf("#define %s %s\n", pairs[i][0], pairs[i][1]);
    puts("#endif");
    return ferror(stdout) ? 1 : 0;
}
