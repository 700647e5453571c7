#!/usr/bin/env bats
# The house's large-scale rules (issue 31), checked so that they hold as
# the code grows: no program or library file over 1000 lines and no
# function over 120, README at most 250 lines, HACKING naming every file
# under lib/ and tools/, no benchmark output among the samples.

load test_helper

@test "no file of lib/ or tools/ over 1000 lines, no function over 120" {
	cd "$TOP"
	run -0 bash -c "git ls-files 'lib/*.[ch]' 'tools/*.[ch]' 'tools/*/*.[ch]' |
	    xargs wc -l | awk '\$2 != \"total\" && \$1 > 1000'"
	[ -z "$output" ]
	# a function: its name at the start of a line, to the brace closing it
	run -0 bash -c "for f in \$(git ls-files 'lib/*.c' 'tools/*.c' 'tools/*/*.c'); do
	    awk -v f=\$f '/^[a-z_][a-zA-Z0-9_]*\\(/ { name = \$0; start = NR }
		/^}/ && start { if (NR - start > 120) print f \": \" name; start = 0 }' \$f; done"
	[ -z "$output" ]
}

@test "README is at most 250 lines; HACKING names every file of lib/ and tools/" {
	cd "$TOP"
	[ "$(wc -l < README)" -le 250 ]
	run -0 bash -c "git ls-files lib tools | grep -v '^tools/bench/results/' |
	    while read -r f; do grep -qF \"\$(basename \"\$f\")\" HACKING || echo \"\$f\"; done"
	[ -z "$output" ]
}

@test "samples/ holds inputs and the gallery, no benchmark output" {
	cd "$TOP"
	run -0 bash -c "git ls-files samples | grep -Ei 'bench|peers|readers' || true"
	[ -z "$output" ]
}
