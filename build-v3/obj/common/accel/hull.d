build-v3/obj/common/accel/hull.o: common/accel/hull.c common/accel/hull.h \
 common/plane.h common/ray.h common/vec.h common/quad.h
common/accel/hull.h:
common/plane.h:
common/ray.h:
common/vec.h:
common/quad.h:
