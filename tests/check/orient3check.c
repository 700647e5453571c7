/*
 * orient3check: the library's orient3d on the points of each line of the
 * standard input, "ax ay az bx by bz cx cy cz dx dy dz": prints its sign,
 * for tests/lib-predicates.bats to compare with exact rationals.  Exit 2
 * on a line it cannot read.
 */
#include <stdio.h>

#include "qtree.h"

int
main(void)
{
	struct point3 p[4];
	int i, n;

	for (;;) {
		for (i = 0; i < 4; i++)
			if ((n = scanf("%lf %lf %lf", &p[i].x, &p[i].y,
			    &p[i].z)) != 3)
				break;
		if (i < 4)
			break;
		printf("%d\n", orient3d(p[0], p[1], p[2], p[3]));
	}
	if (i != 0 || n != EOF) {
		fprintf(stderr, "orient3check: a line of 12 numbers expected\n");
		return 2;
	}
	return 0;
}
