/*
 * rcm.c: the vertices' numbers as written.  Without -r a vertex keeps the
 * number of its first use; with -r it is renumbered by reverse
 * Cuthill-McKee: breadth first from a pseudo-peripheral vertex of each
 * connected part (George and Liu: the vertex of least degree in the last
 * level, while that lengthens the search), neighbours taken by increasing
 * degree, the order then reversed.  Vertices are neighbours when an
 * element holds both.  The graph lives only while rcm runs; the mesh
 * keeps the permutation (perm) alone.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtmesh.h"

/* Vertex i's neighbours, from 0: adj[adjoff[i]..adjoff[i + 1]). */
struct graph {
	uint32_t	*adj, *adjoff, *deg;
};

/* The largest difference of vertex numbers within an element. */
uint32_t
bandwidth(const struct mesh *m)
{
	const struct elem *elems = m->elems;
	const uint32_t *perm = m->perm;
	uint32_t bw = 0, lo, hi, v;
	size_t i;
	int k;

	for (i = 0; i < m->nelems; i++) {
		lo = hi = perm[elems[i].v[0] - 1];
		for (k = 1; k < nverts(&elems[i]); k++) {
			v = perm[elems[i].v[k] - 1];
			lo = v < lo ? v : lo;
			hi = v > hi ? v : hi;
		}
		bw = hi - lo > bw ? hi - lo : bw;
	}
	return bw;
}

static void
buildgraph(struct graph *gr, const struct mesh *m, size_t nv)
{
	const struct elem *elems = m->elems;
	size_t i, n;
	uint32_t *fill, *adj, *adjoff, a, b, w, j, k, lo;
	int p, q;

	adjoff = gr->adjoff = xreallocarray(NULL, nv + 1, sizeof(*adjoff));
	fill = xreallocarray(NULL, nv + 1, sizeof(*fill));
	memset(adjoff, 0, (nv + 1) * sizeof(*adjoff));
	for (i = 0; i < m->nelems; i++)
		for (p = 0; p < nverts(&elems[i]); p++)
			adjoff[elems[i].v[p]] += nverts(&elems[i]) - 1;
	for (i = 1; i <= nv; i++)
		adjoff[i] += adjoff[i - 1];
	adj = gr->adj = xreallocarray(NULL, adjoff[nv] + 1, sizeof(*adj));
	memcpy(fill, adjoff, (nv + 1) * sizeof(*fill));
	for (i = 0; i < m->nelems; i++)
		for (p = 0; p < nverts(&elems[i]); p++)
			for (q = 0; q < nverts(&elems[i]); q++)
				if (p != q) {
					a = elems[i].v[p] - 1;
					b = elems[i].v[q] - 1;
					adj[fill[a]++] = b;
				}
	/* each list sorted and without repeats, packed to the left */
	gr->deg = xreallocarray(NULL, nv, sizeof(*gr->deg));
	w = 0;
	for (i = 0; i < nv; i++) {
		lo = adjoff[i];
		n = adjoff[i + 1] - lo;
		for (j = 1; j < n; j++)	/* insertion sort: short lists */
			for (k = j; k > 0 && adj[lo + k - 1] > adj[lo + k]; k--) {
				a = adj[lo + k];
				adj[lo + k] = adj[lo + k - 1];
				adj[lo + k - 1] = a;
			}
		adjoff[i] = w;
		for (j = 0; j < n; j++)
			if (j == 0 || adj[lo + j] != adj[lo + j - 1])
				adj[w++] = adj[lo + j];
		gr->deg[i] = w - adjoff[i];
	}
	adjoff[nv] = w;
	free(fill);
}

/* Breadth first from s over unplaced vertices into q; the last level. */
static size_t
bfs(const struct graph *gr, uint32_t s, uint32_t *q, uint32_t *dist,
    const char *placed, size_t *lastlevel, uint32_t stamp, uint32_t *seen)
{
	size_t head = 0, tail = 0, j;

	q[tail++] = s;
	seen[s] = stamp;
	dist[s] = 0;
	*lastlevel = 0;
	while (head < tail) {
		uint32_t v = q[head++];

		if (dist[v] != dist[q[*lastlevel]])
			*lastlevel = head - 1;
		for (j = gr->adjoff[v]; j < gr->adjoff[v + 1]; j++) {
			uint32_t w = gr->adj[j];

			if (!placed[w] && seen[w] != stamp) {
				seen[w] = stamp;
				dist[w] = dist[v] + 1;
				q[tail++] = w;
			}
		}
	}
	return tail;
}

void
rcm(struct mesh *m, size_t nv)
{
	struct graph gr;
	const uint32_t *deg;
	uint32_t *order, *q, *dist, *seen, stamp = 0, s, best, v, w, t;
	char *placed;
	size_t n = 0, i, j, k, last, len, head, cnt, ecc;

	buildgraph(&gr, m, nv);
	deg = gr.deg;
	order = xreallocarray(NULL, nv + 1, sizeof(*order));
	q = xreallocarray(NULL, nv + 1, sizeof(*q));
	dist = xreallocarray(NULL, nv + 1, sizeof(*dist));
	seen = xreallocarray(NULL, nv + 1, sizeof(*seen));
	placed = xmalloc(nv + 1);
	memset(placed, 0, nv + 1);
	memset(seen, 0, (nv + 1) * sizeof(*seen));
	for (i = 0; i < nv; i++) {
		if (placed[i])
			continue;
		s = i;
		len = bfs(&gr, s, q, dist, placed, &last, ++stamp, seen);
		ecc = dist[q[len - 1]];
		for (;;) {
			best = q[last];
			for (k = last; k < len; k++)
				if (deg[q[k]] < deg[best])
					best = q[k];
			len = bfs(&gr, best, q, dist, placed, &last, ++stamp,
			    seen);
			if (dist[q[len - 1]] <= ecc) {
				s = best;
				break;
			}
			ecc = dist[q[len - 1]];
			s = best;
		}
		/* Cuthill-McKee from s: each vertex's new neighbours by degree */
		head = n;
		order[n++] = s;
		placed[s] = 1;
		while (head < n) {
			v = order[head++];
			cnt = n;
			for (j = gr.adjoff[v]; j < gr.adjoff[v + 1]; j++) {
				w = gr.adj[j];
				if (!placed[w]) {
					placed[w] = 1;
					order[n++] = w;
				}
			}
			for (j = cnt + 1; j < n; j++)
				for (k = j; k > cnt && (deg[order[k - 1]] >
				    deg[order[k]] || (deg[order[k - 1]] ==
				    deg[order[k]] && order[k - 1] > order[k]));
				    k--) {
					t = order[k];
					order[k] = order[k - 1];
					order[k - 1] = t;
				}
		}
	}
	for (i = 0; i < nv; i++)
		m->perm[order[i]] = nv - i;
	free(order);
	free(q);
	free(dist);
	free(seen);
	free(placed);
	free(gr.adj);
	free(gr.adjoff);
	free(gr.deg);
}

/* Vertex i + 1 as it is written, in the order of the new numbers. */
uint32_t *
inverse(const struct mesh *m, size_t nv)
{
	uint32_t *inv = xreallocarray(NULL, nv + 1, sizeof(*inv));
	size_t i;

	for (i = 0; i < nv; i++)
		inv[m->perm[i] - 1] = i + 1;
	return inv;
}
