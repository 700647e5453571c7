#!/usr/bin/env bats
# qtmesh -f inp: the Abaqus/CalculiX deck, its sets and surfaces by ring
# edge, read by CalculiX itself where it is installed.

load test_helper

@test "-f inp: each ring edge's node set lies on that edge, by coordinates" {
	run bash -c 'qtsplit -l 6 "$SAMPLES/quarter-plate.qt" | qtbalance |
	    qtmesh -b -f inp > mesh.inp &&
	    awk -F", *" "/^\\*/ { set = \"\"; if (\$0 ~ /^\\*NODE,/) mode = \"n\";
	        else if (\$1 == \"*NSET\") { mode = \"s\"; sub(/NSET=/, \"\", \$2); set = \$2 }
	        else mode = \"\"; next }
	        mode == \"n\" { x[\$1] = \$2; y[\$1] = \$3 }
	        mode == \"s\" { for (i = 1; i <= NF; i++) if (\$i != \"\") {
	            n = \$i; bad = 0
	            if (set == \"R1E1\" && y[n] != 0) bad = 1
	            if (set == \"R1E2\" && x[n] != 1) bad = 1
	            if (set == \"R1E3\" && y[n] != 1) bad = 1
	            if (set == \"R1E4\" && x[n] != 0) bad = 1
	            if (set == \"R1E5\" && ((x[n]^2 + y[n]^2 - 0.01)^2 > 1e-24)) bad = 1
	            if (bad) { print set, n, x[n], y[n]; exit 1 }
	            seen[set]++ } }
	        END { for (s in seen) print s, seen[s] }" mesh.inp | sort'
	[ "$status" -eq 0 ]
	[ "${lines[0]%% *}" = R1 ]
	[ "${lines[1]%% *}" = R1E1 ]
	[ "${lines[5]%% *}" = R1E5 ]
	[ "${#lines[@]}" -eq 6 ]
}

@test "-f inp: CalculiX solves the plate, the reaction balances the load" {
	command -v ccx > /dev/null || skip "no ccx (Debian calculix-ccx)"
	qtsplit -l 7 "$SAMPLES/quarter-plate.qt" | qtbalance |
	    qtmesh -b -f inp > mesh.inp
	cat > plate.inp <<-'DECK'
	*INCLUDE, INPUT=mesh.inp
	*MATERIAL, NAME=M
	*ELASTIC
	1000., 0.3
	*SOLID SECTION, ELSET=EALL, MATERIAL=M
	1.
	*STEP
	*STATIC
	*BOUNDARY
	R1E1, 2
	R1E4, 1
	*DSLOAD
	R1E2, P, -1.
	*NODE PRINT, NSET=R1E4, TOTALS=ONLY
	RF
	*END STEP
	DECK
	run ccx plate
	[ "$status" -eq 0 ]
	# the load is 1 on the side x = 1 of length 1: the supports at x = 0
	# give it back (a face taken wrongly would give another total)
	run awk '/total force/ { getline; getline; print $1 }' plate.dat
	[ "$status" -eq 0 ]
	awk -v f="$output" 'BEGIN { exit !(f + 1 < 1e-9 && f + 1 > -1e-9) }'
}

@test "-e without -f inp, -f inp with -H and an unknown family are refused" {
	run qtmesh -e CPS < /dev/null
	[ "$status" -eq 2 ]
	run qtmesh -H -f inp < /dev/null
	[ "$status" -eq 2 ]
	run qtmesh -f inp -e XYZ < /dev/null
	[ "$status" -eq 2 ]
	[[ "$output" == *"unknown element family XYZ"* ]]
}
