/*
 * The persistent harness of FUZZMODE=fast (run.sh): runs a program's main,
 * renamed fuzzmain by persist.h, once for each input AFL++ writes, in one
 * process, instead of forking a new process each time (forks cost about a
 * millisecond here).  Each run starts as a fresh process would: the
 * program's variables with static storage are restored from a copy taken
 * before the first run, getopt starts again, and the files the last run
 * left open are closed.  exit longjmps back here; standard output is
 * flushed instead of closed.  Built without persist.h.
 */
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int fuzzmain(int, char *[]);

extern char __start_qtdata[], __stop_qtdata[];
extern char __start_qtbss[], __stop_qtbss[];

static jmp_buf back;
static FILE *opened[64];
static int nopened;

_Noreturn void
fuzzexit(int status)
{
	(void)status;
	longjmp(back, 1);
}

FILE *
fuzzfopen(const char *path, const char *mode)
{
	FILE *fp = fopen(path, mode);

	if (fp != NULL && nopened < 64)
		opened[nopened++] = fp;
	return fp;
}

int
fuzzfclose(FILE *fp)
{
	int i;

	if (fp == stdout || fp == stderr || fp == stdin)
		return fflush(fp) == EOF || ferror(fp) ? EOF : 0;
	for (i = 0; i < nopened; i++)
		if (opened[i] == fp) {
			opened[i] = opened[--nopened];
			break;
		}
	return fclose(fp);
}

#ifndef __AFL_LOOP
/*
 * Without afl-clang-fast, to try the harness itself: PERSIST_RUNS runs
 * (default 1) on the same operands, whose outputs must all be the same.
 */
#define __AFL_INIT() ((void)0)
static long runs = -1;
#define __AFL_LOOP(n) (runs < 0 ? (runs = getenv("PERSIST_RUNS") ? \
    atol(getenv("PERSIST_RUNS")) - 1 : 0, 1) : runs-- > 0)
#endif

int
main(int argc, char *argv[])
{
	size_t ndata = __stop_qtdata - __start_qtdata;
	size_t nbss = __stop_qtbss - __start_qtbss;
	char *data = malloc(ndata + 1), *bss = malloc(nbss + 1);
	char **args = malloc((argc + 1) * sizeof *args);

	if (data == NULL || bss == NULL || args == NULL)
		return 1;
	memcpy(data, __start_qtdata, ndata);
	memcpy(bss, __start_qtbss, nbss);
	__AFL_INIT();
	while (__AFL_LOOP(1000)) {
		memcpy(__start_qtdata, data, ndata);
		memcpy(__start_qtbss, bss, nbss);
		memcpy(args, argv, (argc + 1) * sizeof *args);
		optind = 1;
		if (setjmp(back) == 0)
			fuzzmain(argc, args);
		fflush(stdout);
		clearerr(stdout);
		while (nopened > 0)
			fclose(opened[--nopened]);
	}
	return 0;
}
