build-v3/obj/gen/05-shadows-scene.o: build-v3/gen/05-shadows-scene.c
