// awkward.pov: written by raygl2pov 0.1.0 from golden.raygl, frame 0 (stream 0, frame 0 of the stream)
// Eye coordinates of the OpenGL frame: x right, y up, the camera looks down -z.
#version 3.7;
global_settings{assumed_gamma 2.2}
camera{perspective
 location <0,0,0>
 right <2,0,0>
 up <0,1.5,0>
 direction <0,0,-1>
}
background{rgb<0,0,0>}
#default{finish{ambient 0 diffuse 0 emission 1}}
union{
sphere{<0,0,-4.99925>,0}
mesh2{
vertex_vectors{6,
<0,0,0.000500025>,
<0.9999,0.9999,0.000500025>,
<1.9998,1.9998,0.000500025>,
<-0.99985,-0.99985,0.0007500375>,
<0,-0.99985,0.0007500375>,
<-0.99985,0,0.0007500375>}
texture_list{2,
texture{pigment{rgb<1,1,1>}},
texture{pigment{rgb<1,0.5,0>}}}
face_indices{1,
<3,5,4>,1}
matrix<0.99995,0,0,0,0.99995,0,0,0,0.99995,0,0,-4.99975>
}
mesh2{
vertex_vectors{10,
<0,0,-4.99875>,
<0.90886366,0,-4.99875>,
<0,0.99975,-4.99875>,
<0,0,-4.9985>,
<0.9997,0,-4.9985>,
<0,0,-3.9988>,
<-0.95497817,-0.7003173,-1.0186434>,
<-0.7003173,-0.7003173,-1.0186434>,
<-0.7003173,-0.5729869,-1.0186434>,
<-0.95497817,-0.5729869,-1.0186434>}
texture_list{2,
texture{pigment{rgb<1,0.5,0>}},
texture{pigment{rgb<1,1,1>}}}
face_indices{4,
<0,2,1>,0,
<3,5,4>,0,
<6,8,7>,1,
<6,9,8>,1}
}
clipped_by{plane{<0,0,1>,-1}plane{<0,0,-1>,20}}
}
