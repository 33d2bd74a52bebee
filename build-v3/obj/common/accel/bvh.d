build-v3/obj/common/accel/bvh.o: common/accel/bvh.c common/accel/bvh.h
common/accel/bvh.h:
