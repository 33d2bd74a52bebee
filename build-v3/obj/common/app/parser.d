build-v3/obj/common/app/parser.o: common/app/parser.c common/app/parser.h \
 common/scene.h common/camera.h common/ray.h common/vec.h common/light.h \
 common/quad.h common/material.h common/plane.h common/sphere.h \
 common/film.h common/app/lexer.h common/material.h
common/app/parser.h:
common/scene.h:
common/camera.h:
common/ray.h:
common/vec.h:
common/light.h:
common/quad.h:
common/material.h:
common/plane.h:
common/sphere.h:
common/film.h:
common/app/lexer.h:
common/material.h:
