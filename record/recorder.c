/* placeholder: being written */
typedef int rgl_placeholder_recorder;
