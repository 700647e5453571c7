/*
 * qtsplit.h: what qtsplit.c hands qtsplit3.c, which splits 3D streams.
 */
struct split3opts {
	int		 minlevel, maxlevel;	/* maxlevel -1: not given */
	int		 cut, cutopt;
	const char	*subtree;
	int		 verbose;
	size_t		 nrl;		/* -L options given */
};

int	 split3main(struct qtreader *, const struct split3opts *);
