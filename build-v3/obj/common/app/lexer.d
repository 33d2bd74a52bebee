build-v3/obj/common/app/lexer.o: common/app/lexer.c common/app/lexer.h \
 common/material.h common/vec.h
common/app/lexer.h:
common/material.h:
common/vec.h:
