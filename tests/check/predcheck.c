/*
 * predcheck: the library's exact predicates on the points of each line of
 * the standard input, "ax ay bx by cx cy dx dy": prints the sign of
 * incircle(a, b, c, d) and of orient2d(a, b, c), for tests/lib-predicates.bats
 * to compare with exact rationals.  Exit 2 on a line it cannot read.
 */
#include <stdio.h>
#include <stdlib.h>

#include "qtree.h"

int
main(void)
{
	double p[8];
	int n;

	while ((n = scanf("%lf %lf %lf %lf %lf %lf %lf %lf", &p[0], &p[1],
	    &p[2], &p[3], &p[4], &p[5], &p[6], &p[7])) == 8)
		printf("%d %d\n", incircle(p[0], p[1], p[2], p[3], p[4], p[5],
		    p[6], p[7]), orient2d(p[0], p[1], p[2], p[3], p[4], p[5]));
	if (n != EOF) {
		fprintf(stderr, "predcheck: a line of 8 numbers expected\n");
		return 2;
	}
	return 0;
}
