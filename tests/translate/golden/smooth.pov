// smooth.pov: written by raygl2pov 0.1.0 from golden.raygl, frame 0 (stream 0, frame 0 of the stream)
// Eye coordinates of the OpenGL frame: x right, y up, the camera looks down -z.
#version 3.7;
global_settings{assumed_gamma 2.2}
camera{perspective
 location <0,0,0>
 right <1.2434871,0,0>
 up <0,0.93261534,0>
 direction <0,0,-1>
}
background{rgb<0.3,0.3,0.3>}
#default{finish{ambient 0 diffuse 0 emission 1}}
union{
sphere{<-1,2.9802322e-8,-6.0827622>,0}
mesh2{
vertex_vectors{3,
<-1,0,0>,
<1,0,0>,
<0,1.5,0>}
texture_list{3,
texture{pigment{rgb<1,0,0>}},
texture{pigment{rgb<0,1,0>}},
texture{pigment{rgb<0,0,1>}}}
face_indices{1,
<0,2,1>,0,2,1}
matrix<1,0,0,0,0.98639387,0.16439898,0,-0.16439898,0.98639387,0,2.9802322e-8,-6.0827622>
}
mesh2{
vertex_vectors{4,
<0,0,0>,
<1,0,0>,
<1,1,0>,
<0,1,0>}
texture_list{2,
texture{pigment{rgb<0,1,1>}},
texture{pigment{rgb<1,0,1>}}}
face_indices{2,
<0,2,1>,0,
<0,3,2>,1}
matrix<1,0,0,0,0.98639387,0.16439898,0,-0.16439898,0.98639387,1.5,-0.32879794,-7.1513557>
}
mesh2{
vertex_vectors{10,
<-3,-1,0>,
<-3,2,0>,
<-1.5,2,0>,
<-1.5,-1,0>,
<0,2,0>,
<0,-1,0>,
<1.5,2,0>,
<1.5,-1,0>,
<3,2,0>,
<3,-1,0>}
texture_list{5,
texture{pigment{rgb<0,0.5,1>}},
texture{pigment{rgb<0.25,0.5,0.75>}},
texture{pigment{rgb<0.5,0.5,0.5>}},
texture{pigment{rgb<0.75,0.5,0.25>}},
texture{pigment{rgb<1,0.5,0>}}}
face_indices{8,
<0,2,1>,0,1,0,
<0,3,2>,0,1,1,
<3,4,2>,1,2,1,
<3,5,4>,1,2,2,
<5,6,4>,2,3,2,
<5,7,6>,2,3,3,
<7,8,6>,3,4,3,
<7,9,8>,3,4,4}
matrix<1,0,0,0,0.98639387,0.16439898,0,-0.16439898,0.98639387,0,0.657596,-10.0283375>
}
clipped_by{plane{<0,0,1>,-1}plane{<0,0,-1>,50}}
}
