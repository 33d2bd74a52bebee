build-v3/obj/gen/08-area-lights-scene.o: \
 build-v3/gen/08-area-lights-scene.c
