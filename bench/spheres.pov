// POV-Ray 3.7 twin of the benchmark scenes (docs/benchmarks.md), written from
// scenes/spheres.scene, antialiasing.scene and area-lights.scene. Declare=Step=
// 5 (hard shadows, the canonical scene), 7 (ambient, point light: steps 06-07)
// or 8 (area light); for 8, Declare=AreaN=n and Declare=AreaAdaptive=a, where
// a = -1 leaves out the `adaptive` keyword: then every one of the n x n
// shadow rays is traced (POV-Ray's `adaptive 0` still subdivides from the
// four corners, which misses occluders between them).
// POV-Ray is left-handed: `right -x*...` mirrors it into the project's
// right-handed world; `angle` is the horizontal field of view; lights fall off
// as 1/r^2 only with fade_power 2; colours stay linear with assumed_gamma 1
// and File_Gamma=1.0 on the command line (bench/run.sh passes it).
#version 3.7;
#ifndef (Step) #declare Step = 5; #end
#ifndef (AreaN) #declare AreaN = 5; #end
#ifndef (AreaAdaptive) #declare AreaAdaptive = 0; #end

global_settings { assumed_gamma 1.0 max_trace_level 1
  #if (Step = 5) ambient_light rgb 0 #end
  #if (Step = 7) ambient_light rgb <0.25, 0.25, 0.3> #end
  #if (Step = 8) ambient_light rgb <0.15, 0.15, 0.18> #end
}
background { rgb <0.1, 0.15, 0.3> }

// fov 40 (vertical) -> horizontal angle 2 atan(tan(20 deg) * aspect).
camera {
  location <0, 2.2, 9> look_at <0, 0.8, 0> up y right -x * image_width / image_height
  angle 2 * degrees(atan(tan(radians(20)) * image_width / image_height))
}

// Phong material: pigment = diffuse colour; the ambient colour defaults to the
// diffuse one (ambient 1 times the pigment); POV-Ray's `phong` is max(0,r.v)^n
// times the light colour (grey: the specular colour's mean).
#macro Mat(D, S, N)
  texture { pigment { rgb D }
    finish { ambient 1 diffuse 1 phong S phong_size N } }
#end
#macro Floor() texture { pigment { rgb 0.7 } finish { ambient 1 diffuse 1 } } #end

plane { y, 0 Floor() }
sphere { <0, 1, 0>, 1 Mat(<0.8, 0.15, 0.1>, 0.6, 64) }
sphere { <-2.3, 0.7, -0.8>, 0.7 Mat(<0.15, 0.7, 0.2>, 0.4, 32) }
sphere { <2.2, 0.8, -0.5>, 0.8 Mat(<0.1, 0.25, 0.8>, 0.8, 128) }
sphere { <-1, 0.4, 1.6>, 0.4 Mat(<0.8, 0.6, 0.15>, 0.733, 256) }
sphere { <1.3, 0.45, 1.8>, 0.45 Mat(<0.85, 0.85, 0.85>, 0.3, 16) }
#if (Step = 7)
  #for (K, 0, 19)
    sphere { <-3.4, 0.15, 2 - 2.5 * K>, 0.15 Mat(<0.85, 0.85, 0.85>, 0.3, 16) }
    sphere { <3.4, 0.15, 2 - 2.5 * K>, 0.15 Mat(<0.85, 0.85, 0.85>, 0.3, 16) }
  #end
#end

// Point light of power P: POV-Ray's fade is 2 / (1 + (d / fade_distance)^2),
// so colour P / 2 with fade_distance 1 gives about P / d^2.
#if (Step = 5)
  light_source { <4, 6, 4> rgb 40 / 2 fade_distance 1 fade_power 2 }
  #declare E = 0.3;
#end
#if (Step = 7)
  light_source { <2.2, 3.2, 2.6> rgb <11, 10.5, 9> / 2 fade_distance 1 fade_power 2 }
  #declare E = 0.3;
#end
#if (Step = 8)
  // Parallelogram corner (-1, 3.3, -0.6), edges (2, 0, 0) and (0, 0.3, 1.2):
  // POV-Ray centres the area light on the light's position.
  light_source { <0, 3.45, 0> rgb <20, 19, 16.5> / 2 fade_distance 1 fade_power 2
    area_light <2, 0, 0>, <0, 0.3, 1.2>, AreaN, AreaN
    #if (AreaAdaptive >= 0) adaptive AreaAdaptive #end
    #ifdef (AreaJitter) jitter #end }
  #declare E = 0.15;
#end
// Directional light, direction (-1, -2, -1), irradiance E.
light_source { <1, 2, 1> * 1000 rgb E parallel point_at <0, 0, 0> }
