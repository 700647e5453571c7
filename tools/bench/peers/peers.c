/*
 * What the harnesses share: the polygon read through libqtree's reader
 * (every record checked, as qtsplit reads it), the level operand, the
 * clock and the report.  No classification here: each harness has its
 * peer's.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

/* The shells of a 3D stream, as one list of vertices and one of triangles. */
void
peer_read3(const char *path, struct solid *s)
{
	struct qtreader *r = qt_openpath(path, QT_NEEDUNIVERSE | QT_SOLIDS);
	struct qt3reader *r3;
	struct qt3rec rec;
	struct qtrec rec2;
	size_t i;

	memset(s, 0, sizeof(*s));
	if (qt_read(r, &rec2) != QT_SOLID)
		die(1, "%s: not a 3D stream", path);
	r3 = qt3_open(r);
	while (qt3_read(r3, &rec) != QT_EOF) {
		const struct shell *g = &rec.shell;

		if (rec.kind == QT_UNIVERSE) {
			s->x0 = rec.u.x0;
			s->y0 = rec.u.y0;
			s->z0 = rec.u.z0;
			s->size = rec.u.size;
		}
		if (rec.kind != QT_SHELL)
			continue;
		if (s->nv + g->nv > UINT32_MAX)
			die(1, "too many vertices: %zu", s->nv + g->nv);
		s->v = xreallocarray(s->v, s->nv + g->nv, 3 * sizeof(*s->v));
		s->t = xreallocarray(s->t, s->nt + g->nt, 3 * sizeof(*s->t));
		for (i = 0; i < g->nv; i++) {
			s->v[3 * (s->nv + i)] = g->v[i].x;
			s->v[3 * (s->nv + i) + 1] = g->v[i].y;
			s->v[3 * (s->nv + i) + 2] = g->v[i].z;
		}
		for (i = 0; i < 3 * g->nt; i++)
			s->t[3 * s->nt + i] = s->nv + g->t[i];
		s->nv += g->nv;
		s->nt += g->nt;
	}
	qt3_close(r3);
	qt_close(r);
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
