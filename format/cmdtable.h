/* cmdtable.h: the machinery that expands format/commands.def.
 *
 * Each row of commands.def is
 *
 *     RGL_CMD(opcode, api, gen, Name, handler, arg, arg, ...)
 *
 * opcode   stable wire opcode (append-only; never renumbered or reused)
 * api      GL, GLU, GLUT, RAY (raygl-only call) or REC (a record the library
 *          writes itself; no API function)
 * gen      AUTO: the recorder entry point is generated from the row;
 *          CUSTOM: it is written by hand in record/ (the args then describe
 *          the wire record, which may differ from the C prototype);
 *          WIRE: no entry point (api REC)
 * Name     the call without its prefix: Vertex3f, Sphere, SolidTeapot. The
 *          API function is raygl + prefix-rest: rayglVertex3f, raygluSphere,
 *          rayglutSolidTeapot; the real one gl/glu/glut + Name.
 * handler  the interpreter's handler (translate/ defines interp_<handler>)
 * args     each one of
 *            P(t, name)          a scalar of wire type t
 *            A(t, name, N)       a pointer to exactly N elements of type t
 *            N(t, name, count)   a pointer to `count` elements, where count is
 *                                an expression over the other parameters; on
 *                                the wire a varint count, then the elements
 *            BLOB(name)          bytes: varint length, then the bytes
 *            STR(name)           a string: varint length, then UTF-8 bytes
 *          or the single token NOARGS.
 *
 * Wire types t: b ub s us (fixed 1/2 bytes), i sz (zigzag varint), ui e bf h
 * (varint), f (IEEE-754 single, 4 bytes), d (double, 8 bytes), bo (1 byte),
 * ip (zigzag varint, 64 bits).
 *
 * Consumers expand an argument list with RGL_MAP(prefix, ...): each element
 * X(...) becomes prefix##X(...), so the same list can give a C parameter
 * list, an encoder body or a descriptor array.
 */
#ifndef RGL_CMDTABLE_H
#define RGL_CMDTABLE_H

#define RGL_CAT_(a, b) a##b
#define RGL_CAT(a, b) RGL_CAT_(a, b)

#define RGL_NARG_(_1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, N, ...) N
#define RGL_NARG(...) RGL_NARG_(__VA_ARGS__, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0)

/* RGL_MAP(M, a, b, c) -> M##a M##b M##c (no separators) */
#define RGL_MAP(M, ...) RGL_CAT(RGL_MAP_, RGL_NARG(__VA_ARGS__))(M, __VA_ARGS__)
#define RGL_MAP_1(M, a) M##a
#define RGL_MAP_2(M, a, ...) M##a RGL_MAP_1(M, __VA_ARGS__)
#define RGL_MAP_3(M, a, ...) M##a RGL_MAP_2(M, __VA_ARGS__)
#define RGL_MAP_4(M, a, ...) M##a RGL_MAP_3(M, __VA_ARGS__)
#define RGL_MAP_5(M, a, ...) M##a RGL_MAP_4(M, __VA_ARGS__)
#define RGL_MAP_6(M, a, ...) M##a RGL_MAP_5(M, __VA_ARGS__)
#define RGL_MAP_7(M, a, ...) M##a RGL_MAP_6(M, __VA_ARGS__)
#define RGL_MAP_8(M, a, ...) M##a RGL_MAP_7(M, __VA_ARGS__)
#define RGL_MAP_9(M, a, ...) M##a RGL_MAP_8(M, __VA_ARGS__)
#define RGL_MAP_10(M, a, ...) M##a RGL_MAP_9(M, __VA_ARGS__)
#define RGL_MAP_11(M, a, ...) M##a RGL_MAP_10(M, __VA_ARGS__)
#define RGL_MAP_12(M, a, ...) M##a RGL_MAP_11(M, __VA_ARGS__)
#define RGL_MAP_13(M, a, ...) M##a RGL_MAP_12(M, __VA_ARGS__)
#define RGL_MAP_14(M, a, ...) M##a RGL_MAP_13(M, __VA_ARGS__)

/* RGL_MAP_LIST(M, a, b) -> M##a, M##b (comma separated) */
#define RGL_MAP_LIST(M, ...) RGL_CAT(RGL_MAPL_, RGL_NARG(__VA_ARGS__))(M, __VA_ARGS__)
#define RGL_MAPL_1(M, a) M##a
#define RGL_MAPL_2(M, a, ...) M##a, RGL_MAPL_1(M, __VA_ARGS__)
#define RGL_MAPL_3(M, a, ...) M##a, RGL_MAPL_2(M, __VA_ARGS__)
#define RGL_MAPL_4(M, a, ...) M##a, RGL_MAPL_3(M, __VA_ARGS__)
#define RGL_MAPL_5(M, a, ...) M##a, RGL_MAPL_4(M, __VA_ARGS__)
#define RGL_MAPL_6(M, a, ...) M##a, RGL_MAPL_5(M, __VA_ARGS__)
#define RGL_MAPL_7(M, a, ...) M##a, RGL_MAPL_6(M, __VA_ARGS__)
#define RGL_MAPL_8(M, a, ...) M##a, RGL_MAPL_7(M, __VA_ARGS__)
#define RGL_MAPL_9(M, a, ...) M##a, RGL_MAPL_8(M, __VA_ARGS__)
#define RGL_MAPL_10(M, a, ...) M##a, RGL_MAPL_9(M, __VA_ARGS__)
#define RGL_MAPL_11(M, a, ...) M##a, RGL_MAPL_10(M, __VA_ARGS__)
#define RGL_MAPL_12(M, a, ...) M##a, RGL_MAPL_11(M, __VA_ARGS__)
#define RGL_MAPL_13(M, a, ...) M##a, RGL_MAPL_12(M, __VA_ARGS__)
#define RGL_MAPL_14(M, a, ...) M##a, RGL_MAPL_13(M, __VA_ARGS__)

/* Names of the API function, the real function and the GL name string. */
#define RGL_APIFN_GL(n) raygl##n
#define RGL_APIFN_GLU(n) raygl##u##n
#define RGL_APIFN_GLUT(n) raygl##ut##n
#define RGL_APIFN_RAY(n) raygl##n
#define RGL_REALFN_GL(n) gl##n
#define RGL_REALFN_GLU(n) glu##n
#define RGL_REALFN_GLUT(n) glut##n
#define RGL_NAMESTR_GL(n) "gl" #n
#define RGL_NAMESTR_GLU(n) "glu" #n
#define RGL_NAMESTR_GLUT(n) "glut" #n
#define RGL_NAMESTR_RAY(n) "raygl" #n
#define RGL_NAMESTR_REC(n) "@" #n

#define RGL_APIFN(api, n) RGL_APIFN_##api(n)
#define RGL_REALFN(api, n) RGL_REALFN_##api(n)
#define RGL_NAMESTR(api, n) RGL_NAMESTR_##api(n)

/* Argument descriptors for the decoder and the dumper. */
#define RGL_DESC_P(t, n) {RGL_ARG_SCALAR, RGL_T_##t, 1, #n},
#define RGL_DESC_A(t, n, cnt) {RGL_ARG_ARRAY, RGL_T_##t, cnt, #n},
#define RGL_DESC_N(t, n, cnt) {RGL_ARG_COUNTED, RGL_T_##t, 0, #n},
#define RGL_DESC_BLOB(n) {RGL_ARG_BLOB, RGL_T_ub, 0, #n},
#define RGL_DESC_STR(n) {RGL_ARG_STRING, RGL_T_ub, 0, #n},
#define RGL_DESC_NOARGS

#define RGL_COUNT_P(t, n) +1
#define RGL_COUNT_A(t, n, cnt) +1
#define RGL_COUNT_N(t, n, cnt) +1
#define RGL_COUNT_BLOB(n) +1
#define RGL_COUNT_STR(n) +1
#define RGL_COUNT_NOARGS

#endif
