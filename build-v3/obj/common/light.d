build-v3/obj/common/light.o: common/light.c common/light.h common/quad.h \
 common/ray.h common/vec.h
common/light.h:
common/quad.h:
common/ray.h:
common/vec.h:
