/*
 * off.c: Object File Format (OFF): a line OFF, counts of vertices, faces
 * and edges, the vertices "x y z" a line, the faces "n i1 ... in" a line
 * with vertices counted from 0; what follows on a line (colours) is
 * ignored, and '#' starts a comment.  The header's prefixes ST, C and N
 * (texture coordinates, colours, normals after each vertex's x y z:
 * COFF, NOFF, CNOFF, STCNOFF) add only what is ignored; 4 and n, which
 * change the dimension, are not read.
 */
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

/* The length of an OFF header word at p, [ST][C][N]OFF; 0 for none. */
static size_t
offheader(const char *p, size_t len)
{
	size_t i = 0;

	if (len >= 2 && memcmp(p, "ST", 2) == 0)
		i = 2;
	if (i < len && p[i] == 'C')
		i++;
	if (i < len && p[i] == 'N')
		i++;
	return len == i + 3 && memcmp(p + i, "OFF", 3) == 0 ? len : 0;
}

/* The first line of data is OFF, alone or before the three counts. */
int
isoff(const struct src *s)
{
	const char *f[4];
	size_t len[4];
	int n = linefields(s->p, f, len, 4);

	return (n == 1 || n == 4) && offheader(f[0], len[0]) > 0;
}

/* Past the rest of the line: fields a format allows and polyread skips. */
void
restofline(struct src *s)
{
	while (*s->p != '\n' && *s->p != '\0')
		s->p++;
}

void
parseoff(struct src *s, struct input *in)
{
	long long nv, nf, i, j, n;
	size_t base, *v = NULL, cap = 0;
	long line;
	size_t len = 0;

	if (skipspace(s))
		len = offheader(s->p, strcspn(s->p, " \t\r\n"));
	if (len == 0)
		badtoken(s, "expected OFF");
	s->p += len;
	nv = integer(s, "number of vertices", 0, (long long)1 << 40);
	nf = integer(s, "number of faces", 1, (long long)1 << 40);
	integer(s, "number of edges", 0, (long long)1 << 40);
	restofline(s);
	base = in->solid != NULL ? in->solid->nv : 0;
	for (i = 0; i < nv; i++) {
		double x, y, z;

		expectmore(s, i, nv, "vertices");
		line = s->line;
		x = number(s, "x");
		y = number(s, "y");
		z = number(s, "z");
		if (s->line != line)
			readerr(s->name, s->line, "vertex %lld of line %ld "
			    "ends early", i, line);
		addpoint3(in, s->name, line, x, y, z);
		restofline(s);
	}
	for (i = 0; i < nf; i++) {
		expectmore(s, i, nf, "faces");
		line = s->line;
		n = integer(s, "face's vertex count", 3, 1 << 20);
		v = xgrow(v, &cap, n, sizeof(*v));
		for (j = 0; j < n; j++) {
			v[j] = base + integer(s, "vertex number", 0, nv - 1);
			if (s->line != line)
				readerr(s->name, line, "face %lld has fewer "
				    "than its %lld vertices on its line", i, n);
		}
		addpoly3(in, s->name, line, v, n);
		restofline(s);
	}
	if (skipspace(s))
		readerr(s->name, s->line, "data after the last of %lld faces",
		    nf);
	free(v);
}
