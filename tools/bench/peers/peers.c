/*
 * What the harnesses share: the polygon read through libqtree's reader
 * (every record checked, as qtsplit reads it), the level operand, the
 * clock and the report.  No classification here: each harness has its
 * peer's.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#include "qtree.h"
#include "peers.h"

void
peer_read(const char *path, struct poly *p)
{
	struct qtreader *r = qt_openpath(path, QT_NEEDUNIVERSE);
	struct qtrec rec;
	enum qtkind k;
	size_t i, cap = 0;

	p->e = NULL;
	p->n = 0;
	while ((k = qt_read(r, &rec)) != QT_EOF) {
		const struct ring *g = &rec.ring;

		if (k == QT_UNIVERSE) {
			p->x0 = rec.u.x0;
			p->y0 = rec.u.y0;
			p->size = rec.u.size;
		}
		if (k != QT_RING)
			continue;
		if (p->n + g->n > cap) {
			cap = 2 * (p->n + g->n);
			p->e = xreallocarray(p->e, cap, sizeof(*p->e));
		}
		for (i = 0; i < g->n; i++) {
			struct point a = g->v[i], b = g->v[(i + 1) % g->n];
			struct pedge *e = &p->e[p->n++];

			e->ax = a.x, e->ay = a.y, e->bx = b.x, e->by = b.y;
			e->xmin = a.x < b.x ? a.x : b.x;
			e->xmax = a.x < b.x ? b.x : a.x;
			e->ymin = a.y < b.y ? a.y : b.y;
			e->ymax = a.y < b.y ? b.y : a.y;
		}
	}
	qt_close(r);
	if (p->n > UINT32_MAX)
		die(1, "too many edges: %zu", p->n);
}

/*
 * The command line, "NAME -l level [file]": the level, from 0 to max, goes
 * to *level; returns the file, "-" for stdin.
 */
const char *
peer_args(int argc, char *argv[], const char *name, int max, int *level)
{
	char line[80];
	const char *end;
	long long v;
	int ch;

	xsetprogname(argv[0]);
	snprintf(line, sizeof(line), "usage: %s -l level [file]\n", name);
	*level = -1;
	while ((ch = getopt(argc, argv, "l:h")) != -1)
		switch (ch) {
		case 'l':
			if (parselong(optarg, &end, &v) < 0 || *end != '\0' ||
			    v < 0 || v > max)
				die(2, "-l: level must be an integer from 0 "
				    "to %d: %s", max, optarg);
			*level = v;
			break;
		default:
			usageexit(ch == 'h', line);
		}
	argc -= optind;
	argv += optind;
	if (argc > 1 || *level < 0)
		usageexit(0, line);
	return argc == 1 ? argv[0] : "-";
}

double
peer_now(void)
{
	struct timespec t;

	clock_gettime(CLOCK_MONOTONIC, &t);
	return t.tv_sec + t.tv_nsec * 1e-9;
}

/* The leaves by class F, E, P, and the seconds, as peers.h says. */
void
peer_print(const unsigned long long n[3], double seconds)
{
	printf("leaves_F %llu\nleaves_E %llu\nleaves_P %llu\nseconds %.6f\n",
	    n[0], n[1], n[2], seconds);
	closeout();
}
