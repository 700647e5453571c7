/*
 * qtstats.h: what qtstats.c hands qtstats3.c, which reads 3D streams.
 */
extern int stats3table;		/* -l */
int	 stats3main(struct qtreader *, int);
