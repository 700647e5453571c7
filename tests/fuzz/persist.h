/*
 * Included first in every source of a persistent fuzz build (FUZZMODE=fast
 * in run.sh), so that persist.c can run a program's main many times in one
 * process: main, exit, fopen and fclose are renamed to persist.c's, and
 * every variable with static storage goes to the sections qtdata and qtbss,
 * which persist.c restores before each run.  Nothing else changes.
 */
#include <stdio.h>
#include <stdlib.h>

#pragma clang section data="qtdata" bss="qtbss"

int fuzzmain(int, char *[]);
_Noreturn void fuzzexit(int);
FILE *fuzzfopen(const char *, const char *);
int fuzzfclose(FILE *);

#define main fuzzmain
#define exit fuzzexit
#define fopen fuzzfopen
#define fclose fuzzfclose
