#!/usr/bin/env python3
"""lunaster under mpirun, through the real CLI (CTest labels: mpi, and mpi_full for the full matrix).

usage: mpi_runs.py CASE LUNASTER MESHGEN SOURCE_DIR SCRATCH_DIR [full]
The suites over testcases/ (verify_suite, shared_suite, parts_suite, contact_parts_suite) run their
representative decks (REPRESENTATIVE, PARTS_REPRESENTATIVE, CONTACT_PARTS_REPRESENTATIVE,
RELATION_REPRESENTATIVE: one for each kind of thing the suite proves, each with its reason), or
with `full` every deck of their matrix.
  verify_suite  the decks `make verify` runs (testcases/), by `lunaster verify` serially and with
                --np 2, both with --json: every TEST_RESU value equal to 1e-8 (compare_checks.py),
                the same decks, checks and statuses; the comparison itself is shown to fail on a
                perturbed value, a missing check and a changed status
  shared_suite  the same decks with every STAT_NON_LINE's model shared among 2 ranks, then 3 (verify
                --np N --solveur=MUMPS: each rank assembles its own nodes, pairs its share of the
                contact points, MUMPS takes the matrix distributed), against the serial run: every deck
                shares its model, the same statuses and checks, every value equal to 1e-8 of
                itself or of its field's scale in the deck (a component zero analytically is
                round-off of that size), but the values of ill-conditioned systems, named with their
                reason in CONDITIONED, to the tolerance their condition number gives; serial AUTO
                against serial MUMPS likewise; and the decks that name PETSc, as written, on 3 ranks
  outputs       `mpirun -np 2 lunaster run` of decks that write MED results (MUMPS), tables and
                IMPR_MESURE, and of an .export with a message file: the files of the serial run,
                MED fields equal to 1e-8 (h5py), the report printed once; rank 1 prints nothing and
                writes nothing (run as MPMD: rank 1 gets an --out folder of its own, which must not
                appear)
  errors        must-fail decks under mpirun -np 2 (a deck error, a singular MUMPS factorisation,
                SOLVEUR RENUM='METIS', which needs the whole matrix in one process):
                the error once with file:line, the exit status of the deck; `lunaster verify` under
                mpirun refuses; verify --np without mpirun on the PATH says so; budgets under
                verify --np 2 (TIMEOUT, OUT_OF_MEMORY); a launcher that outlives the time limit
                is asked to end (SIGTERM) and the deck reported TIMEOUT
  parts_suite   the linear-elastic decks with every mesh read in parts (LIRE_MAILLAGE PARTITIONNEUR), on 1, 2
                and 3 ranks, against the serial run on whole meshes: values to 1e-8 of themselves or of
                their field's scale, the MED file and the table IMPR_RESU writes; errors found on one
                rank's part (a node name no part holds, an AXIS cell at x < 0) stop every rank with
                one error and the deck's status; IMPR_MESURE's row counts the whole mesh; the tables
                POST_RELEVE_T makes are the serial ones on every rank (reactions_tables.lua)
  contact_parts_suite  the contact decks a mesh in parts takes (every method; 2D, AXIS, 3D; MUMPS and
                PETSc) and the decks of linear relations (LIAISON_DDL, LIAISON_UNIF, LIAISON_MAIL; with
                multipliers and ELIM_LAGR) with every mesh read in parts, on 1, 2 and 3 ranks, against
                the serial run on whole meshes, as parts_suite; discrete contact's QUAD8 ties and a
                failed solve's converged steps in parts; a solver of one process, LDLT_SP and an
                unknown relation node refused on every rank with one message
  rank_failure  a rank that fails alone brings the run down: a budget stop inside the collective
                MUMPS factorisation (time limit on every rank; memory limit on rank 0 only, then
                on rank 1 only); a rank that stops on a deck error while the other waits for it in
                MUMPS (the end-of-run wait, then MPI_Abort with the rank's status); ranks that end
                with different statuses (the worst wins, rank 0 shows the other rank's error).
                Rank-local failures are made by MPMD runs (each rank its own deck or limit).
mpirun settings for a root user on a small machine are set here (never in lunaster), each one
kept if the environment gives it.
"""
import concurrent.futures
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import compare_checks  # noqa: E402
sys.path.insert(0, str(HERE.parent / "budget"))
from run_budget_tests import LOOP_LIMIT, SANITIZED  # noqa: E402

failures = []
ENV = dict(os.environ)
for key, value in {
    "OMPI_ALLOW_RUN_AS_ROOT": "1",  # CI runs as root
    "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
    "OMPI_MCA_rmaps_base_oversubscribe": "1",  # more ranks than cores (verify -j 2 --np 2 on 2 cores)
    "OMPI_MCA_mpi_yield_when_idle": "1",  # waiting ranks yield the core (oversubscribed)
    "OMPI_MCA_pml": "ob1",  # one machine: shared memory, no UCX probing (0.2 s a start)
    "OMPI_MCA_btl": "self,vader",
    "OMPI_MCA_btl_vader_single_copy_mechanism": "none",  # containers may forbid cross-memory attach
}.items():
    ENV.setdefault(key, value)
# The end-of-run wait of a rank that stopped on an error (lua/main.cpp kRankWaitSeconds).
RANK_WAIT_SECONDS = 10.0
WAITERS = concurrent.futures.ThreadPoolExecutor(max_workers=2)  # runs that mostly wait


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def run(args, cwd, env=None, timeout=300):
    """Runs a command; `timeout` guards against a hang (four times longer in a sanitizer build,
    which runs the decks several times slower), it is not a time bound of the test."""
    start = time.monotonic()
    proc = subprocess.run([str(a) for a in args], cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=timeout * (4 if SANITIZED else 1), env=env or ENV)
    seconds = time.monotonic() - start
    print(f"$ {' '.join(str(a) for a in args)}  -> exit {proc.returncode} in {seconds:.2f} s")
    return proc.returncode, proc.stdout, proc.stderr, seconds


def mpirun():
    path = shutil.which("mpirun", path=ENV.get("PATH"))
    if not path:
        sys.exit("mpirun is not on the PATH (Debian: openmpi-bin)")
    return path


def mpmd(exe, rank0_args, rank1_args, logs):
    """mpirun with one rank per argument list (MPMD), each rank's output kept under `logs`."""
    return [mpirun(), "--output-filename", logs, "-np", 1, exe, *rank0_args, ":", "-np", 1, exe, *rank1_args]


def rank_output(logs, rank):
    folder = Path(logs) / "1" / f"rank.{rank}"
    return "".join((folder / s).read_text() if (folder / s).exists() else "" for s in ("stdout", "stderr"))


def test_lines(text):
    return [l for l in text.splitlines() if compare_checks.CHECK.match(l)]


# ---------------------------------------------------------------------------------------------
# What the suites over testcases/ run. `make test` (CTest label mpi) runs each on the decks below,
# one for each kind of thing the full matrix proves; the full matrix, every deck of testcases/
# (CTest label mpi_full: `make test-mpi-full`, which CI runs too), is the same code on more decks.
# A sanitizer build runs this set as well: the whole suite four times over would take an hour there.
REPRESENTATIVE = {
    "distributed_solvers": "METHODE='MUMPS' and 'PETSC' named by the deck, 3D: the model shared, each rank "
                           "assembling its nodes and computing CALC_CHAMP on its cells (verify_suite reads its log)",
    "petsc_solvers": "PETSc's preconditioners on a shared model, contact in 3D; its ML smoothing once stopped CG on 3 "
                     "ranks",
    "ssnp121a": "2D QUAD4 on non-matching meshes, CONTINUE (Simpson): the contact points shared among the ranks",
    "ssnp121b": "discrete CONTRAINTE: the active set with Lagrange multipliers over the ranks",
    "ssnp121c": "discrete PENALISATION, 2D",
    "ssnp121a_mortar": "mortar LAGRANGIEN, 2D",
    "axis_contact_patch_mortar": "AXIS, mortar PENALISATION",
    "axis_contact_patch_discrete": "AXIS, discrete contact",
    "ssnp121h": "QUAD8 with SEG3 master faces, 2D, CONTACT_INIT='INTERPENETRE'",
    "ssnp121d_discrete": "HEXA20 with QUAD8 faces, 3D: the discrete mid-side ties (multipliers and ELIM_LAGR), a "
                         "penalty of E_N = 1e12 on E = 2e6 (CONDITIONED names its tolerance)",
    "ssnp121e": "PENTA15 with TRIA6 faces, 3D CONTINUE",
    "ssnp121i": "HEXA8 on HEXA20 non-matching, 3D CONTINUE (the three-rank hang was in such a scene)",
    "ssnp121k": "PENTA6 on HEXA20, TRIA3 slave on QUAD8 master",
    "patch_3d": "TETRA and HEXA elasticity, 3D, no contact: the plain shared assembly",
    "liaison_ddl": "LIAISON_DDL and LIAISON_UNIF, with multipliers and ELIM_LAGR",
    "liaison_mail": "LIAISON_MAIL gluing non-matching meshes (TETRA faces), DISTANCE_MAX",
    "mesh_in_parts": "a deck that reads its mesh in parts (PARTITIONNEUR): it solves on them, not on a shared model",
    "solver_singularity": "ill-conditioned by design (NPREC, STOP_SINGULIER, a stiff penalty): CONDITIONED names "
                          "its tolerances",
}
# A failure as a deck's status: the same under every run (testcases/errors/, named as a file).
FAILING = {"errors/contact_step_no_subdivision": "a solve that fails to converge: exit 3, its converged steps saved"}


# Decks that run on one process only, each with its reason: the full matrix takes every other deck
# of testcases/, and `errors` checks that mpirun refuses these with the reason, once.
SERIAL_ONLY = {"vmis_isot_line_bar": "von Mises plasticity (COMPORTEMENT VMIS_ISOT_LINE, VMIS_ISOT_TRAC): the "
                                     "driver assembles a nonlinear behaviour on a whole model only, and refuses a "
                                     "model shared among ranks",
               "grot_gdep_stretch": "large rotations (COMPORTEMENT DEFORMATION='GROT_GDEP'): a nonlinear response, "
                                    "refused on a model shared among ranks as above",
               "friction_patch_2d": "Coulomb friction (DEFI_CONTACT FROTTEMENT='COULOMB'): the contact points' "
                                    "friction states are not shared among ranks, refused there",
               "friction_patch_3d": "Coulomb friction, as friction_patch_2d",
               "cattaneo_cylinder": "Coulomb friction, as friction_patch_2d",
               "friction_sliding_limit": "Coulomb friction, as friction_patch_2d",
               "friction_step_subdivision": "Coulomb friction, as friction_patch_2d",
               "test_references": "VMIS_ISOT_LINE (its stresses at integration points, SIEF_ELGA, for TEST_RESU's "
                                  "per-cell forms): a nonlinear behaviour, refused on a model shared among ranks"}


def suite_decks(full):
    """The paths `verify` runs in source: testcases/ whole but SERIAL_ONLY (its folders as folders,
    verify walks them), or the representative decks; the failing ones too."""
    if full:
        top = sorted((HERE.parent.parent / "testcases").iterdir())
        decks = [f"testcases/{p.name}" for p in top
                 if (p.is_dir() and p.name not in ("errors", "lib")) or
                 (p.suffix in (".lua", ".export", ".comm") and p.stem not in SERIAL_ONLY)]
    else:
        decks = [f"testcases/{d}.lua" for d in REPRESENTATIVE]
    return decks + [f"testcases/{d}.lua" for d in FAILING]


# Values whose round-off exceeds the suite's rule (1e-8 of themselves or of their field's scale)
# because their system is ill-conditioned, named per deck and check label (a pattern of the check's
# description: field, place, component, LEGENDE), each with its reason and its tolerance. Any other
# value that differs fails. A solve of n unknowns with a matrix of condition number kappa gives them
# to about sqrt(n) kappa eps of their scale (eps = 2.2e-16; sqrt(n) is the usual rule of thumb for
# the growth of rounding errors over a factorisation, whose bound has n), and each ordering of the
# factorisation (serial CHOLMOD or MUMPS, MUMPS on 2 or 3 processes, whose pivot order and tree of
# fronts depend on the processes and, on several, on their load) rounds differently within it.
EPS = sys.float_info.epsilon


class Conditioned:
    def __init__(self, deck, label, kappa, unknowns, reason):
        self.deck, self.label, self.kappa, self.unknowns, self.reason = deck, label, kappa, unknowns, reason
        self.tolerance = math.sqrt(unknowns) * kappa * EPS


CONDITIONED = [
    # SSNP121 D: two unit cubes stacked (L = 2), 4x4x4 HEXA20 each (h = 0.25; 850 nodes, 2550
    # unknowns). The penalty springs against the column of material they press, E_N L / E = 1e6
    # (CHOLMOD's pivot test measures it: with NPREC = 6 its PENE run stops on a pivot that lost 6.2
    # digits, with 7 it runs), times the elastic stiffness's own condition (L / h)^2 = 64: kappa =
    # 6.4e7, 7.2e-7 of the scale (its runs with the ties' multipliers, which the pivot test does not
    # see, move most). Its CONTRAINTE run, exact to 1e-14, prints the same labels.
    Conditioned("ssnp121d_discrete", r"^(SIGM_NOEU|SIGM_ELNO|DEPL) ", 1e12 * 2.0 / 2e6 * (2.0 / 0.25) ** 2, 2550,
                "PENALISATION E_N = 1e12 Pa/m on E = 2e6 Pa: MUMPS on 2 ranks moved SIZZ by 2.7e-8 of its scale, "
                "on 3 ranks by 3.5e-8"),
    # AXIS, node springs of E_N = 1e12 N/m per radian on E = 2e6, 2 x (12x12 + 11x11) QUAD4 (626
    # unknowns): CHOLMOD's pivot test stops its PENALISATION runs at NPREC = 7 on a pivot that lost
    # 7.2 digits and passes them at 8: kappa = 10^7.2, 8.8e-8 (its stresses moved by 0.73e-8 of their
    # scale on 2 ranks, 0.69e-8 on 3, in a run where no other value of testcases/ came closer).
    Conditioned("axis_contact_patch_discrete", r"PENALISATION\]$", 10 ** 7.2, 626,
                "discrete PENALISATION E_N = 1e12 N/m per radian on E = 2e6 Pa, AXIS"),
    # Part (1) hangs a block of E = 2e6 from one of 2e-3 (313 nodes, 626 unknowns): a pivot loses
    # 9.3 digits (errors/singular_soft_link_nprec.lua stops on it), kappa = 10^9.3; 1.1e-5.
    Conditioned("solver_singularity", r"^DEPL .*\[NPREC=12\]", 10 ** 9.3, 626,
                "a stiffness ratio of 1e9 (NPREC = 12): the translation of the stiff block is the soft link's"),
    # Part (3), SSNP121 C's scene with E_N = 1e14: a pivot loses 8.1 digits
    # (errors/penalty_too_stiff_nprec.lua), kappa = 10^8.1; 7.0e-7.
    Conditioned("solver_singularity", r"^DEPL .*\[E_N=1e14 ", 10 ** 8.1, 626,
                "a penalty of E_N = 1e14 on E = 2e6 (NPREC = 10)"),
]


def conditioned(deck, what):
    """The CONDITIONED entry of a check (the deck's path, the check's description), or None."""
    return next((c for c in CONDITIONED if Path(deck).stem == c.deck and re.search(c.label, what)), None)


def show_conditioned(stats, what):
    """Prints, per named entry, the largest difference against what the default rule allows."""
    for c, share in stats["wider"].items():
        print(f"  {what}: {c.deck} {c.label}: {share:.2f} of the default 1e-8; allowed {c.tolerance:.1e} ({c.reason})")


def verify_suite(exe, source, scratch, full):
    scratch.mkdir(parents=True)
    serial, parallel = scratch / "serial.json", scratch / "np2.json"
    common = ["verify", *suite_decks(full), "-j", "2", "--vale-calc=report"]
    code_s, out_s, err_s, t_s = run([exe, *common, "--out", scratch / "serial", "--json", serial], source)
    code_p, out_p, err_p, t_p = run([exe, *common, "--np", "2", "--out", scratch / "np2", "--json", parallel], source)
    print(f"serial verify {t_s:.1f} s, verify --np 2 {t_p:.1f} s")
    for out in (out_s, out_p):
        print("  " + "\n  ".join(out.strip().splitlines()[-2:]))
    check(code_s == code_p, f"the same verify exit status serially and with --np 2 ({code_s}, {code_p})")
    a, b = compare_checks.decks(serial), compare_checks.decks(parallel)
    check(len(a) > 50 if full else len(a) == len(REPRESENTATIVE) + len(FAILING),
          f"the suite is {'the whole of testcases/' if full else 'REPRESENTATIVE'} and FAILING ({len(a)} decks)")
    problems, stats = compare_checks.compare(a, b, 1e-8, 1e-8)
    for p in problems[:40]:
        print("  DIFFERENT  " + p)
    print(f"  {stats['decks']} decks, {stats['checks']} values, largest relative difference {stats['largest_rel']:.2e} "
          f"({stats['largest_where']})")
    check(not problems, f"every TEST_RESU value of --np 2 equals the serial one to 1e-8 ({len(problems)} difference(s))")
    total = sum(len(compare_checks.checks(d["output"])) for d in a.values())
    check(stats["checks"] == total > (2000 if full else 900), f"every check of every deck was compared ({stats['checks']} "
                                                              f"of {total})")
    n_mpi_solves = sum("using MUMPS" in d["output"] or "METHODE='MUMPS'" in d["output"] for d in b.values())
    check(n_mpi_solves > (20 if full else 4),
          f"decks that factorise with MUMPS across the ranks are part of it ({n_mpi_solves})")
    # METHODE='MUMPS' or 'PETSC' without contact: the model is shared among the ranks, each
    # assembling its own nodes' stiffness (its values are among those compared above).
    shared = "testcases/distributed_solvers.lua"
    n_shared = b[shared]["output"].count("model shared among 2 ranks, 2 on this machine (Scotch)")
    check(n_shared == 11, f"{shared}: each of its 11 solves (2 with contact) shares the model among the 2 ranks ({n_shared})")
    check("model shared" not in a[shared]["output"], f"{shared}: a serial run shares nothing")
    # Its CALC_CHAMP (SIGM_NOEU, REAC_NODA) computes each cell on the rank that held it.
    split = re.findall(r"CALC_CHAMP: each rank computes the cells it held in STAT_NON_LINE \(this rank (\d+) of (\d+)\)",
                       b[shared]["output"])
    check(len(split) == 8 and all(0 < int(m) < int(n) for m, n in split),
          f"{shared}: each of its 8 CALC_CHAMP computes a part of the cells on rank 0 ({split})")
    check("CALC_CHAMP: each rank" not in a[shared]["output"], f"{shared}: a serial CALC_CHAMP computes every cell")
    failing = "testcases/errors/contact_step_no_subdivision.lua"
    check(a[failing]["exit_code"] == b[failing]["exit_code"] == 3, f"{failing}: exit 3 serially and with --np 2")

    # The comparison can fail: a value off by 1e-7, a check gone, a status changed.
    name = next(n for n in sorted(b) if test_lines(b[n]["output"]))
    line = test_lines(b[name]["output"])[0]
    calc = float(re.search(r"calc=(\S+)", line).group(1))
    perturbed = line.replace(re.search(r"calc=(\S+)", line).group(0), f"calc={calc * (1 + 1e-7) + 1e-7:.9e}")
    for what, edit, says in (
            ("a value off by 1e-7", lambda o: o.replace(line, perturbed, 1), "calc="),
            ("a check missing", lambda o: o.replace(line + "\n", "", 1), "check(s) against"),
            ("a status changed", lambda o: o.replace(line, ("NOOK" if line.startswith(" OK") else " OK ") + line[4:], 1),
             "' against '")):
        changed = json.loads(json.dumps(b))
        changed[name]["output"] = edit(changed[name]["output"])
        found, _ = compare_checks.compare(a, changed, 1e-8, 1e-8)
        check(len(found) >= 1 and says in found[0], f"the comparison finds {what} in {name} ({found[:1]})")
    changed = dict(b)
    del changed[name]
    found, _ = compare_checks.compare(a, changed, 1e-8, 1e-8)
    check(len(found) == 1, "the comparison finds a deck missing")


def shared_suite(exe, source, scratch, full):
    scratch.mkdir(parents=True)
    decks = suite_decks(full)
    common = ["verify", *decks, "--vale-calc=report"]
    reports, codes = {}, {}
    # Three ranks as well as two: a rank may then hold no contact column at all, and nodes are
    # shared by three ranks (one decision taken on a rank's own columns hung such a run).
    for key, extra in (("serial", ["-j", "2"]), ("serial_mumps", ["-j", "2", "--solveur=MUMPS"]),
                       ("np2_mumps", ["-j", "2", "--np", "2", "--solveur=MUMPS"]),
                       ("np3_mumps", ["-j", "1", "--np", "3", "--solveur=MUMPS"])):
        json_file = scratch / f"{key}.json"
        codes[key], out, _, seconds = run([exe, *common, *extra, "--out", scratch / key, "--json", json_file], source,
                                          timeout=600)
        print(f"  {key}: {seconds:.1f} s; " + " / ".join(out.strip().splitlines()[-1:]))
        reports[key] = compare_checks.decks(json_file)
    s, m = reports["serial"], reports["serial_mumps"]
    check(len(set(codes.values())) == 1, f"the same verify exit status in the four runs ({codes})")
    check(len(s) > 50 if full else len(s) == len(REPRESENTATIVE) + len(FAILING),
          f"the suite is {'the whole of testcases/' if full else 'REPRESENTATIVE'} and FAILING ({len(s)} decks)")
    check(not any("model shared" in d["output"] for d in list(s.values()) + list(m.values())),
          "the serial runs share nothing")
    # Two serial solvers (AUTO, MUMPS) already give the ill-conditioned values differently: within
    # their conditioning, as every other value within the rule.
    problems, stats = compare_checks.compare(s, m, 1e-8, 1e-8, field_scale=True, wider=conditioned)
    for problem in problems[:40]:
        print("  DIFFERENT  " + problem)
    show_conditioned(stats, "serial MUMPS")
    check(not problems, f"serial AUTO and serial MUMPS give every value to 1e-8 of itself or of its field's scale, "
                        f"CONDITIONED's to their tolerance ({len(problems)} difference(s))")
    solving = [n for n, d in s.items() if "STAT_NON_LINE" in d["output"] or "MECA_NON_LINE" in d["output"]]
    for ranks in (2, 3):
        p = reports[f"np{ranks}_mumps"]
        # A deck that reads its mesh in parts (PARTITIONNEUR) solves on them rather than sharing a whole model.
        unshared = [n for n in solving if n not in p or (f"model shared among {ranks} ranks" not in p[n]["output"] and
                                                         f"mesh in parts on {ranks} ranks" not in p[n]["output"])]
        check(len(solving) >= (50 if full else len(REPRESENTATIVE)) and not unshared,
              f"{ranks} ranks: every deck that solves ({len(solving)}) shares its model among them (not: {unshared[:5]})")
        check(all("--solveur=MUMPS" in p[n]["output"] for n in solving if n in p),
              f"{ranks} ranks: each of their STAT_NON_LINE says that the command line chose MUMPS")
        # MUMPS on several processes chooses the processes that share a front's work from their load
        # as it goes: two runs of one deck round off differently, within the same conditioning.
        problems, stats = compare_checks.compare(s, p, 1e-8, 1e-8, field_scale=True, wider=conditioned)
        for problem in problems[:40]:
            print("  DIFFERENT  " + problem)
        show_conditioned(stats, f"{ranks} ranks")
        print(f"  {ranks} ranks: {stats['decks']} decks, {stats['checks']} values; the largest difference is "
              f"{stats['largest_share']:.2f} of the one allowed ({stats['share_where']})")
        check(not problems, f"{ranks} ranks: every value of the shared model equals the serial one to 1e-8 of itself "
                            f"or of its field's scale, CONDITIONED's to their tolerance ({len(problems)} difference(s))")
        total = sum(len(compare_checks.checks(d["output"])) for d in s.values())
        check(stats["checks"] == total > (3000 if full else 900),
              f"{ranks} ranks: every check of every deck was compared ({stats['checks']} of {total})")

    # The decks that name PETSc, as written, on 3 ranks (verify_suite runs them on 2): PETSc's
    # default ML smoothing, SOR within each rank, made CG stop on an indefinite V-cycle there.
    petsc = ["testcases/petsc_solvers.lua", "testcases/distributed_solvers.lua"]
    json_file = scratch / "np3_petsc.json"
    code, _, _, seconds = run([exe, "verify", *petsc, "--np", "3", "--out", scratch / "np3_petsc", "--json", json_file],
                              source)
    print(f"  np3_petsc: {seconds:.1f} s")
    p = compare_checks.decks(json_file)
    problems, stats = compare_checks.compare({n: s[n] for n in petsc}, p, 1e-8, 1e-8, field_scale=True)
    for problem in problems[:20]:
        print("  DIFFERENT  " + problem)
    check(code == 0 and not problems and stats["checks"] > 150,
          f"3 ranks: the PETSc decks as written give the serial values ({len(problems)} difference(s), "
          f"{stats['checks']} values, exit {code})")
    check(p["testcases/petsc_solvers.lua"]["output"].count("model shared among 3 ranks") >= 4,
          "3 ranks: petsc_solvers.lua shares its models")

    # The field-scale floor still sees a near-zero value moved by 1e-7 of its field's scale, and a
    # CONDITIONED stress moved by twice its tolerance is seen too.
    p = reports["np2_mumps"]

    def what(line):
        return compare_checks.CHECK.match(line).group(3)

    for label, pick, size in (
            ("a zero stress", lambda n, l: "refe=0.000000000e+00" in l and conditioned(n, what(l)) is None, lambda c: 1e-7),
            ("a CONDITIONED stress", lambda n, l: conditioned(n, what(l)) is not None, lambda c: 2 * c.tolerance)):
        name, number, line = next((n, k + 1, l) for n in sorted(p) for k, l in enumerate(test_lines(p[n]["output"]))
                                  if "SIGM_NOEU" in l and pick(n, l))
        moved = size(conditioned(name, what(line)))
        scale = compare_checks.field_scales(compare_checks.checks(s[name]["output"]))["SIGM_NOEU"]
        calc = float(re.search(r"calc=(\S+)", line).group(1))
        changed = json.loads(json.dumps(p))
        changed[name]["output"] = p[name]["output"].replace(line, line.replace(
            re.search(r"calc=(\S+)", line).group(0), f"calc={calc + moved * scale:.9e}"), 1)
        found, _ = compare_checks.compare(s, changed, 1e-8, 1e-8, field_scale=True, wider=conditioned)
        check(any(f"{name}: check {number} " in f for f in found),
              f"the comparison finds {label} of {name} moved by {moved:.1e} of its field's scale {scale:.3g} "
              f"({found[:1]})")


# ---------------------------------------------------------------------------------------------
def med_datasets(path):
    import h5py
    import numpy

    out = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset):
            out[name] = numpy.array(obj[()])
        for key, value in obj.attrs.items():
            out[f"{name}@{key}"] = numpy.array(value)

    with h5py.File(path, "r") as f:
        f.visititems(visit)
    return out


def same_med(a, b, field_scale=False, rel=1e-8, least_scale=1.0):
    """Differences between two MED files: the same datasets and attributes, floats to `rel` (of
    themselves or `rel`; with `field_scale`, or of the largest value of their dataset: a value zero
    analytically is round-off of its field's size, which two solvers give differently; a dataset's
    scale is at least `least_scale`)."""
    import numpy

    da, db = med_datasets(a), med_datasets(b)
    problems = [f"{k}: only in {a.name} of the serial run" for k in sorted(set(da) - set(db))]
    problems += [f"{k}: only in the mpirun file" for k in sorted(set(db) - set(da))]
    n_values = 0
    for key in sorted(set(da) & set(db)):
        x, y = da[key], db[key]
        if x.shape != y.shape or x.dtype != y.dtype:
            problems.append(f"{key}: {x.dtype}{x.shape} against {y.dtype}{y.shape}")
        elif numpy.issubdtype(x.dtype, numpy.floating):
            n_values += x.size
            floor = rel * max(float(numpy.abs(x).max(initial=0.0)), least_scale) if field_scale else rel
            bad = numpy.abs(x - y) > numpy.maximum(rel * numpy.maximum(numpy.abs(x), numpy.abs(y)), floor)
            if bad.any():
                i = int(numpy.argmax(bad.ravel()))
                problems.append(f"{key}: {int(bad.sum())} value(s) differ, first {x.ravel()[i]!r} against {y.ravel()[i]!r}")
        elif not numpy.array_equal(x, y):
            problems.append(f"{key}: differs")
    return problems, len(da), n_values


def same_table(a, b, rel=1e-8):
    """Differences between two text results (IMPR_RESU FORMAT='RESULTAT', IMPR_TABLE): the same text
    but numbers, each to `rel` of itself or of the largest value of its field at its step (of the
    file, for a table)."""
    number = re.compile(r"[-+]?\d+\.\d+[eE][-+]\d+")
    la, lb = a.read_text().splitlines(), b.read_text().splitlines()
    if len(la) != len(lb):
        return [f"{len(la)} lines against {len(lb)}"]
    problems = []
    scale = max([abs(float(v)) for l in la for v in number.findall(l)], default=0.0)
    for k, (x, y) in enumerate(zip(la, lb)):
        if x.startswith("CHAMP"):
            # the field's values: the lines up to the next CHAMP (not this line's INST)
            block = la[k + 1:k + 1 + next((j for j, l in enumerate(la[k + 1:]) if l.startswith("CHAMP")), len(la))]
            scale = max([abs(float(v)) for l in block for v in number.findall(l)], default=0.0)
        nx, ny = number.findall(x), number.findall(y)
        if number.sub("#", x).split() != number.sub("#", y).split():  # a sign moves the column's spaces
            problems.append(f"line {k + 1}: {x!r} against {y!r}")
        elif any(abs(float(u) - float(v)) > max(rel * max(abs(float(u)), abs(float(v))), rel * scale)
                 for u, v in zip(nx, ny)):
            problems.append(f"line {k + 1}: {x!r} against {y!r}")
    return problems


def output_files(folder):
    return sorted(str(p.relative_to(folder)) for p in Path(folder).rglob("*") if p.is_file())


def outputs(exe, source, scratch):
    scratch.mkdir(parents=True)
    case = scratch / "case"
    case.mkdir()
    shutil.copy(source / "testcases" / "comm" / "ssnp121a.comm", case)
    (case / "study.export").write_text(
        f"P time_limit 60\nP memory_limit 512\nF comm ssnp121a.comm D 1\nF mmed {source}/testcases/ssnp121a.med D 20\n"
        "F rmed contact_result.rmed R 80\nF mess study.mess R 6\n")
    decks = [source / "testcases" / "ssnp121a.lua", source / "testcases" / "reactions_tables.lua",
             source / "testcases" / "loads_and_groups.lua", case / "study.export",
             source / "testcases" / "distributed_solvers.lua",  # the model shared among the ranks
             source / "testcases" / "errors" / "contact_step_no_subdivision.lua"]  # exit 3, converged steps saved
    serial_checks = {}
    for deck in decks:
        name = deck.stem
        want = 3 if deck.parent.name == "errors" else 0
        extra = ["--vale-calc=report"] if deck.suffix == ".export" else []
        serial_out, rank0_out, rank1_out = scratch / f"{name}.serial", scratch / f"{name}.rank0", scratch / f"{name}.rank1"
        code_s, out_s, err_s, _ = run([exe, "run", deck, "--out", serial_out, *extra], scratch)
        logs = scratch / f"{name}.logs"
        code_m, out_m, err_m, _ = run(mpmd(exe, ["run", deck, "--out", rank0_out, *extra],
                                           ["run", deck, "--out", rank1_out, *extra], logs), scratch)
        check(code_s == want and code_m == want,
              f"{name}: exit {want} serially and under mpirun -np 2 ({code_s}, {code_m})")
        files = output_files(serial_out)
        check(len(files) > 0 and output_files(rank0_out) == files,
              f"{name}: rank 0 writes the files of the serial run, no more, no less ({files})")
        check(not rank1_out.exists(), f"{name}: rank 1 writes nothing (its --out folder does not exist)")
        check(rank_output(logs, 1) == "", f"{name}: rank 1 prints nothing (stdout and stderr empty)")
        meds = [f for f in files if f.endswith(".rmed")]
        for med in meds:
            problems, n_sets, n_values = same_med(serial_out / med, rank0_out / med)
            for p in problems[:10]:
                print("  " + p)
            check(not problems and n_values > 0,
                  f"{name}: {med} of mpirun equals the serial one ({n_sets} datasets/attributes, {n_values} floats to 1e-8)")
        if want:
            error = [l for l in err_m.splitlines() if re.search(re.escape(deck.name) + r":\d+: STAT_NON_LINE", l)]
            check(len(error) == 1, f"{name}: the error once, with file:line ({len(error)})")
            check(str(rank0_out / f"{name}_converged.rmed") in err_m, f"{name}: it names rank 0's converged-steps file")
            continue
        check(err_m == "", f"{name}: nothing on the standard error of the run")
        summary = [l for l in out_m.splitlines() if re.match(r"lunaster: \d+ check\(s\) OK", l)]
        check(len(summary) == 1, f"{name}: the report's summary is printed once ({len(summary)})")
        serial_checks[name] = len(test_lines(out_s))
        check(len(test_lines(out_m)) == serial_checks[name] > 0,
              f"{name}: the TEST_RESU lines printed once each ({len(test_lines(out_m))}, serially {serial_checks[name]})")
        if name == "distributed_solvers":  # contact on a shared model: the ranks share the pairing
            check("pairs its share of the contact points" in out_m,
                  f"{name}: the log says the ranks share the contact pairing")
            check("model shared among 2 ranks, 2 on this machine" in out_m,
                  f"{name}: the log counts the ranks on this machine (MPI_COMM_TYPE_SHARED)")
        if deck.suffix == ".export":
            check((rank0_out / "study.mess").read_text() == out_m + err_m,
                  "the .export's message file (rank 0's) holds what the run printed")
    check(any(f.endswith(".rmed") for d in decks for f in output_files(scratch / f"{d.stem}.serial")),
          "MED files were compared")

    # A plain `mpirun -np 2` (one --out for both ranks): exactly one MED file, no temporary left.
    code, out, err, _ = run([mpirun(), "-np", 2, exe, "run", source / "testcases" / "ssnp121a.lua", "--out", "plain"],
                            scratch)
    check(code == 0 and output_files(scratch / "plain") == ["ssnp121a_80.rmed"],
          f"mpirun -np 2: exactly one MED file in the output folder ({output_files(scratch / 'plain')})")
    check(out.count("check(s) OK") == 1 and len(test_lines(out)) == serial_checks["ssnp121a"],
          f"mpirun -np 2: the TEST_RESU lines and the summary once ({len(test_lines(out))} lines)")


# ---------------------------------------------------------------------------------------------
# The decks of testcases/ that are linear elasticity with what a mesh in parts takes today
# (docs/distributed-model.md, step 4): their meshes are read in parts for parts_suite.
PARTS_DECKS = ["patch_2d", "patch_3d", "axis_patch", "axis_thick_cylinder", "clockwise_2d_pressure", "glued_ssnp121_2d",
               "glued_ssnp121_3d", "reactions_tables", "force_face", "pesanteur", "first_deck"]
# What a deck of linear elasticity alone does not use (contact_parts_suite takes the decks of
# contact and of linear relations; parts_suite's 'mesure' case runs IMPR_MESURE).
BEYOND_ELASTICITY = re.compile(r"\b(IMPR_MESURE|DEFI_CONTACT|DEFI_CONT|CONTACT|LIAISON_DDL|LIAISON_UNIF|LIAISON_MAIL)\b")
# The contact decks of testcases/ that a mesh in parts takes (docs/distributed-model.md, step 5):
# every method (CONTINUE, the discrete CONTRAINTE and PENALISATION, mortar's LAGRANGIEN and
# PENALISATION), 2D, AXIS and 3D, MUMPS and PETSc; not the decks with LIAISON_MAIL or solver
# options that gather the whole system on one rank (contact_parts_suite checks that those are
# refused).
CONTACT_PARTS_DECKS = ["axis_contact_patch_continue", "axis_contact_patch_discrete", "axis_contact_patch_mortar",
                       "clockwise_2d_contact", "contact_step_subdivision", "contact_tole_proj_ext",
                       "hertz_cylinder_dplan", "hertz_sphere_3d", "hertz_sphere_axis", "mortar_bimaterial_2d",
                       "mortar_bimaterial_3d", "mortar_petsc_in_parts", "mortar_rotated_2d", "mortar_rotated_3d",
                       "mortar_two_zones_2d", "mortar_two_zones_3d", "newton_matrix_policy", "ring_sleeve_mortar",
                       "ring_sleeve_mortar_quad8", "solver_singularity", "ssnp121a", "ssnp121a_fine",
                       "ssnp121a_mortar", "ssnp121a_mortar_dist", "ssnp121a_mortar_meca_non_line",
                       "ssnp121a_seed_syntax", "ssnp121b", "ssnp121b_mortar", "ssnp121c", "ssnp121c_mortar",
                       "ssnp121d", "ssnp121d_mortar", "ssnp121e", "ssnp121e_mortar", "ssnp121e_simpson", "ssnp121f",
                       "ssnp121f_mortar", "ssnp121f_mortar_quad8_on_tria6", "ssnp121f_quad8_on_tria6", "ssnp121g",
                       "ssnp121g_mortar", "ssnp121h", "ssnp121h_mortar", "ssnp121h_mortar_seg3_slave", "ssnp121i",
                       "ssnp121i_mortar", "ssnp121j", "ssnp121j_mortar", "ssnp121k", "ssnp121k_mortar",
                       "ssnp121k_mortar_quad4_on_tria6", "ssnp121k_quad4_on_tria6"]
# Decks with linear relations (LIAISON_DDL, LIAISON_UNIF, LIAISON_MAIL), with multipliers and
# solved for one unknown each (ELIM_LAGR). Discrete contact's QUAD8 ties (ssnp121d_discrete.lua)
# are run in parts by contact_parts_suite against the deck's own checks: its penalty run (E_N =
# 1e12 on E = 2e6) rounds its stresses off at 1e-8 of their scale, differently for every ordering
# (MUMPS on 1, 2 and 3 processes of the shared model: A21's SIZZ -1.000000054e5, -1.000000055e5,
# -1.000000052e5; on 3 parts -1.000000044e5).
RELATION_PARTS_DECKS = ["liaison_ddl", "liaison_mail", "liaison_mail_periodic", "liaison_mail_sliding",
                        "relations_in_parts", "ring_sleeve_liaison_mail", "ssnp121a_mortar_relation"]
# What `make test` runs of the three lists above (the full lists: CTest label mpi_full), one deck
# for each kind of thing they prove; mesh_in_parts.lua always (parts_suite's errors are made from it).
PARTS_REPRESENTATIVE = {
    "patch_3d": "3D, HEXA and TETRA cells cut among the parts",
    "axis_thick_cylinder": "AXIS, a pressure on a curved boundary cut among the parts",
    "glued_ssnp121_2d": "2D, two bodies glued on non-matching meshes",
    "reactions_tables": "POST_RELEVE_T's tables, the serial ones on every rank",
}
CONTACT_PARTS_REPRESENTATIVE = {
    "axis_contact_patch_mortar": "AXIS, mortar PENALISATION",
    "ssnp121b": "discrete CONTRAINTE, 2D",
    "ssnp121c": "discrete PENALISATION, 2D",
    "ssnp121a_mortar": "mortar LAGRANGIEN, 2D QUAD4 on non-matching meshes",
    "ssnp121h": "QUAD8 on SEG3 master faces, 2D CONTINUE (CONTACT_INIT='INTERPENETRE')",
    "ssnp121d": "HEXA20 with QUAD8 faces, 3D CONTINUE",
    "ssnp121j": "PENTA6 on PENTA15, TRIA3 on TRIA6 faces, 3D",
    "mortar_petsc_in_parts": "PETSc on a mesh in parts, mortar in 3D",
    "solver_singularity": "ill-conditioned by design: CONDITIONED's tolerances in parts",
}
RELATION_REPRESENTATIVE = {
    "liaison_ddl": "LIAISON_DDL and LIAISON_UNIF, with multipliers and ELIM_LAGR",
    "liaison_mail": "LIAISON_MAIL, its slave and master nodes in different parts (ghosts)",
}


def case_ranks(full):
    """The rank counts of the parts suites' single runs (errors, refusals, ties, a failed solve): 2
    and 3 in the full matrix; 3 in `make test`, where a rank may hold no contact column and nodes are
    shared by three (the decks' matrix runs 1, 2 and 3 ranks in both)."""
    return (2, 3) if full else (3,)


def in_parts_against_serial(exe, source, scratch, names, least_checks, least_med_values, two_solvers=False):
    """The decks `names` of testcases/ with every mesh read in parts, run by `lunaster verify` on 1,
    2 and 3 ranks, against their serial run on whole meshes: the same checks and statuses, every
    value to 1e-8 of itself or of its field's scale (CONDITIONED's to their tolerance), and the same
    output files (MED files and tables likewise, each MED file with floats, more than `least_med_values` in all).
    With `two_solvers`, serial AUTO against serial MUMPS as well. Returns the folders of the decks on
    whole meshes and in parts."""
    scratch.mkdir(parents=True)
    whole, parts = scratch / "whole", scratch / "parts"
    for folder in (whole, parts):
        shutil.copytree(source / "testcases", folder / "testcases", ignore=shutil.ignore_patterns("errors", "comm"))
    for name in names:
        text = (source / "testcases" / f"{name}.lua").read_text()
        # The serial reference reads whole meshes; the runs in parts read every mesh in parts.
        plain = text.replace(", PARTITIONNEUR = 'PTSCOTCH'", "")
        (whole / "testcases" / f"{name}.lua").write_text(plain)
        in_parts, n = re.subn(r"LIRE_MAILLAGE\s*\{", "LIRE_MAILLAGE{ PARTITIONNEUR = 'PTSCOTCH',", plain)
        check(n > 0, f"{name}: its meshes are read in parts ({n} LIRE_MAILLAGE)")
        (parts / "testcases" / f"{name}.lua").write_text(in_parts)
    decks = [f"testcases/{n}.lua" for n in names]
    reports, codes = {}, {}
    runs = [("serial", whole, ["-j", "2"])]
    if two_solvers:
        runs.append(("serial_mumps", whole, ["-j", "2", "--solveur=MUMPS"]))
    runs += [("np1", parts, ["-j", "2"]), ("np2", parts, ["-j", "1", "--np", "2"]),
             ("np3", parts, ["-j", "1", "--np", "3"])]
    for key, cwd, extra in runs:
        json_file = scratch / f"{key}.json"
        codes[key], out, _, seconds = run([exe, "verify", *decks, "--vale-calc=report", *extra, "--out", scratch / key,
                                           "--json", json_file], cwd, timeout=600)
        print(f"  {key}: {seconds:.1f} s; " + " / ".join(out.strip().splitlines()[-1:]))
        reports[key] = compare_checks.decks(json_file)
    check(set(codes.values()) == {0}, f"every run passes every check ({codes})")
    s = reports["serial"]
    check(len(s) == len(decks) and not any("mesh in parts" in d["output"] for d in s.values()),
          f"the serial reference reads whole meshes ({len(s)} decks)")
    if two_solvers:
        problems, stats = compare_checks.compare(s, reports["serial_mumps"], 1e-8, 1e-8, field_scale=True, wider=conditioned)
        for problem in problems[:20]:
            print("  DIFFERENT  " + problem)
        show_conditioned(stats, "serial MUMPS")
        check(not problems, f"serial AUTO and serial MUMPS give every value to 1e-8 of itself or of its field's scale, "
                            f"CONDITIONED's to their tolerance ({len(problems)} difference(s))")
    for key, ranks in (("np1", 1), ("np2", 2), ("np3", 3)):
        p = reports[key]
        solves = {n: p[n]["output"].count(f"mesh in parts on {ranks} ranks") for n in p}
        check(len(p) == len(decks) and all(c > 0 for c in solves.values()),
              f"{ranks} rank(s): every deck solves on its mesh in parts ({solves})")
        problems, stats = compare_checks.compare(s, p, 1e-8, 1e-8, field_scale=True, wider=conditioned)
        for problem in problems[:20]:
            print("  DIFFERENT  " + problem)
        show_conditioned(stats, f"{ranks} rank(s)")
        print(f"  {ranks} rank(s): {stats['decks']} decks, {stats['checks']} values; the largest difference is "
              f"{stats['largest_share']:.2f} of the one allowed ({stats['share_where']})")
        total = sum(len(compare_checks.checks(d["output"])) for d in s.values())
        check(not problems and stats["checks"] == total > least_checks,
              f"{ranks} rank(s): every value in parts equals the whole mesh's to 1e-8 ({len(problems)} difference(s), "
              f"{stats['checks']} of {total} values)")
    # The MED files and the tables IMPR_RESU writes: rank 0 gathers every field on the whole mesh.
    serial_files = output_files(scratch / "serial")
    for key in ("np1", "np2", "np3"):
        check(output_files(scratch / key) == serial_files, f"{key}: the files of the serial run ({output_files(scratch / key)})")
        med_values = 0
        for f in serial_files:
            a, b = scratch / "serial" / f, scratch / key / f
            if f.endswith(".rmed"):
                problems, n_sets, n_values = same_med(a, b, field_scale=True)
                med_values += n_values
                for problem in problems[:10]:
                    print("  " + problem)
                check(not problems and n_values > 0,
                      f"{key}: {f} equals the serial one ({n_sets} datasets/attributes, {n_values} floats to 1e-8 of "
                      f"themselves or of their field's scale)")
            else:  # IMPR_RESU's and IMPR_TABLE's text files
                problems = same_table(a, b)
                check(not problems, f"{key}: {f} as the serial one, numbers to 1e-8 ({problems[:2]})")
        # A small deck's MED file (the first deck's: 971 floats) counts; the suite's files together
        # must be more than `least_med_values` floats.
        check(med_values > least_med_values, f"{key}: {med_values} MED floats compared (more than {least_med_values})")
    return whole, parts


def parts_suite(exe, source, scratch, full):
    """Linear-elastic decks with their meshes read in parts, under mpirun -np 2 and 3, against the
    serial run of the same decks on whole meshes: the same checks and statuses, every value to 1e-8
    of itself or of its field's scale, the same MED file, and errors found on one rank's part
    stopping every rank alike."""
    check(set(PARTS_REPRESENTATIVE) <= set(PARTS_DECKS), "PARTS_REPRESENTATIVE is a part of PARTS_DECKS")
    names = (PARTS_DECKS if full else list(PARTS_REPRESENTATIVE)) + ["mesh_in_parts"]
    for name in names:
        text = (source / "testcases" / f"{name}.lua").read_text()
        check(not BEYOND_ELASTICITY.search(text), f"{name}: a deck of linear elasticity alone")
    _, parts = in_parts_against_serial(exe, source, scratch, names, 300 if full else 150, 10000)
    check(any(f.endswith("mesh_in_parts_80.rmed") for f in output_files(scratch / "serial")),
          f"the serial run wrote the MED file")

    # The table comparison can fail: a number moved by 1e-7 of its field's scale.
    table = scratch / "np2" / "mesh_in_parts" / "mesh_in_parts_8.resu"
    moved = scratch / "moved.resu"
    lines = table.read_text().splitlines()
    last = re.findall(r"[-+]?\d+\.\d+e[-+]\d+", lines[-2])[-1]
    lines[-2] = lines[-2].replace(last, f"{float(last) * (1 + 1e-7):.8e}")
    moved.write_text("\n".join(lines) + "\n")
    check(len(same_table(table, moved)) == 1, f"the table comparison finds a number moved by 1e-7 ({lines[-2]})")

    # Errors found on parts: each stops every rank alike, said once, with the deck's exit status.
    deck = parts / "testcases" / "mesh_in_parts.lua"
    text = deck.read_text()
    cases = [
        # a node name no part holds: decided over the ranks
        ("no_node", text.replace("{ NOEUD = 'N2197' }", "{ NOEUD = 'N99999' }"),
         r"mesh_in_parts_no_node\.lua:\d+: TEST_RESU: RESU\[3\]\.NOEUD: expected a node name of the mesh, got 'N99999'"),
        # a node another rank holds is found by its owner alone: no error
        ("corner", text.replace("{ NOEUD = 'N2197' }", "{ NOEUD = 'N1' }").replace("-1.110918013e-03, { NOEUD", "0.0, { NOEUD"),
         None),
        # code_aster 17's MECA_NON_LINE solves on the parts as STAT_NON_LINE does: the same values
        ("meca", text.replace("R = STAT_NON_LINE{", "R = MECA_NON_LINE{"), None),
        # an AXIS model of a mesh with nodes at x < 0 in some parts only: the rank that finds one stops all
        ("axis", "DEBUT()\nMA = LIRE_MAILLAGE{ FICHIER = 'meshes/glued2d_quad4.med', PARTITIONNEUR = 'PTSCOTCH' }\n"
                 "MO = AFFE_MODELE{ MAILLAGE = MA, AFFE = _F{ TOUT = 'OUI', PHENOMENE = 'MECANIQUE', "
                 "MODELISATION = 'AXIS' } }\nFIN()\n",
         r"AFFE_MODELE: AFFE(\[1\])?\.MODELISATION: expected 'AXIS' cells with every node at x = r >= 0"),
        # IMPR_MESURE on a result in parts: the whole mesh's nodes, the unknowns over the ranks, the
        # largest error over them (DX at the top corner C111, against its own value: 0)
        ("mesure", text.replace("FIN()", "IMPR_MESURE{ RESULTAT = R, FICHIER = 'cost.txt', ERREUR = _F{ NOM = 'err', "
                                         "NOM_CHAM = 'DEPL', NOM_CMP = 'DZ', GROUP_NO = 'C111', VALE_REFE = 1.0 } }\n"
                                         "FIN()"), None),
    ]
    mesure = {}
    for name, changed, says in cases:
        path = deck.with_name(f"mesh_in_parts_{name}.lua")
        path.write_text(changed)
        for ranks in case_ranks(full):
            code, out, err, _ = run([mpirun(), "-np", ranks, exe, "run", path, "--out", scratch / f"{name}{ranks}"],
                                    parts, timeout=120)
            if says is None:
                check(code == 0 and out.count("check(s) OK, 0 NOOK") == 1 and "mesh in parts on" in out,
                      f"{name}, {ranks} ranks: every check passes on the mesh in parts (exit {code})")
                if name == "corner":
                    check(re.search(r"^ OK .*DEPL  N1  DZ", out, re.M), f"{name}, {ranks} ranks: node N1 found by its owner")
                if name == "mesure":
                    lines = (scratch / f"{name}{ranks}" / "cost.txt").read_text().splitlines()
                    row = dict(zip(lines[0].split(","), lines[1].split(","))) if len(lines) == 2 else {}
                    check(row.get("nodes") == "2197" and row.get("unknowns") == "6591" and "err" in row,
                          f"{name}, {ranks} ranks: one row, the whole mesh's nodes and unknowns ({row})")
                    mesure[ranks] = float(row.get("err", "nan"))
                continue
            lines = [l for l in err.splitlines() if re.search(says, l)]
            check(code == 2 and len(lines) == 1,
                  f"{name}, {ranks} ranks: exit 2 and the error once ({code}, {len(lines)}: {err.strip()[:300]})")

    # C111 (N2197) has DZ = -1.110918013e-03 (the deck's check): its error against 1 is 1.00111,
    # found by the rank holding it whatever the cut (IMPR_MESURE writes 6 digits).
    check(all(abs(e - 1.001110918) < 1e-5 for e in mesure.values()) and len(mesure) == len(case_ranks(full)),
          f"IMPR_MESURE's error in parts is the largest over the ranks ({mesure})")


def contact_parts_suite(exe, source, scratch, full):
    """The contact decks a mesh in parts takes (CONTACT_PARTS_DECKS) and the decks of linear relations
    (RELATION_PARTS_DECKS) with their meshes read in parts, on 1, 2 and 3 ranks, against the serial
    run on whole meshes (in_parts_against_serial); each rank works on the whole contact surfaces and
    on every relation's nodes. What parts do not take yet is refused on every rank with one message
    and the deck's status."""
    for name in CONTACT_PARTS_DECKS:
        text = (source / "testcases" / f"{name}.lua").read_text()
        check(re.search(r"\b(DEFI_CONTACT|DEFI_CONT|CONTACT)\b", text), f"{name}: a contact deck")
    for name in RELATION_PARTS_DECKS:
        text = (source / "testcases" / f"{name}.lua").read_text()
        check(re.search(r"\b(LIAISON_DDL|LIAISON_UNIF|LIAISON_MAIL)\b|QUAD8", text),
              f"{name}: a deck of linear relations")
    check(set(CONTACT_PARTS_REPRESENTATIVE) <= set(CONTACT_PARTS_DECKS)
          and set(RELATION_REPRESENTATIVE) <= set(RELATION_PARTS_DECKS),
          "CONTACT_PARTS_REPRESENTATIVE and RELATION_REPRESENTATIVE are parts of the full lists")
    contact = CONTACT_PARTS_DECKS if full else list(CONTACT_PARTS_REPRESENTATIVE)
    relations = RELATION_PARTS_DECKS if full else list(RELATION_REPRESENTATIVE)
    names = contact + relations
    _, parts = in_parts_against_serial(exe, source, scratch, names, 2100 if full else 400, 1000, two_solvers=True)
    for key, ranks in (("np2", 2), ("np3", 3)):
        outputs = compare_checks.decks(scratch / f"{key}.json")
        said = {"contact": "the contact surfaces are whole on every rank", "relations": "every rank builds every "
                "linear relation"}
        whole = [n for n, d in outputs.items()
                 if Path(n).stem in contact and said["contact"] not in d["output"]
                 or Path(n).stem in relations and said["relations"] not in d["output"]]
        check(not whole, f"{ranks} ranks: every deck works on the whole contact surfaces and relations ({whole[:3]})")
    # Discrete contact's QUAD8 ties in parts, with multipliers and solved for one unknown each (the
    # deck's CHOLMOD, which parts refuse, made MUMPS): every check of the deck passes on 2 and 3 ranks.
    text = (source / "testcases" / "ssnp121d_discrete.lua").read_text()
    check("METHODE = 'CHOLMOD', ELIM_LAGR" in text, "ssnp121d_discrete: its ELIM_LAGR run asks for CHOLMOD")
    path = parts / "testcases" / "ssnp121d_discrete_mumps.lua"
    path.write_text(re.sub(r"LIRE_MAILLAGE\s*\{", "LIRE_MAILLAGE{ PARTITIONNEUR = 'PTSCOTCH',", text)
                    .replace("METHODE = 'CHOLMOD', ELIM_LAGR", "METHODE = 'MUMPS', ELIM_LAGR"))
    for ranks in case_ranks(full):
        code, out, err, _ = run([mpirun(), "-np", ranks, exe, "run", path, "--out", scratch / f"ties{ranks}"],
                                path.parent, timeout=120)
        check(code == 0 and out.count("80 check(s) OK, 0 NOOK") == 1 and f"mesh in parts on {ranks} ranks" in out
              and "each solved for one of its unknowns" in out,
              f"ssnp121d_discrete (MUMPS), {ranks} ranks: the QUAD8 ties in parts, every check passes (exit {code})")

    # A failed solve in parts keeps its converged steps as a serial run does: rank 0 writes them,
    # gathered on the whole mesh, to the serial run's file.
    name = "contact_step_no_subdivision"
    text = (source / "testcases" / "errors" / f"{name}.lua").read_text()
    path = parts / "testcases" / "errors" / f"{name}.lua"
    path.parent.mkdir(exist_ok=True)
    path.write_text(re.sub(r"LIRE_MAILLAGE\s*\{", "LIRE_MAILLAGE{ PARTITIONNEUR = 'PTSCOTCH',", text))
    code, _, _, _ = run([exe, "run", source / "testcases" / "errors" / f"{name}.lua", "--out", scratch / "failed"],
                        scratch, timeout=120)
    saved = scratch / "failed" / f"{name}_converged.rmed"
    check(code == 3 and saved.exists(), f"{name}: serially exit 3 and its converged steps saved ({code})")
    for ranks in case_ranks(full):
        out_dir = scratch / f"failed{ranks}"
        code, out, err, _ = run([mpirun(), "-np", ranks, exe, "run", path, "--out", out_dir], path.parent, timeout=120)
        said = [l for l in err.splitlines() if f"saved in {out_dir / (name + '_converged.rmed')}" in l]
        check(code == 3 and len(said) == 1 and "mesh in parts on" in out,
              f"{name}, {ranks} ranks: exit 3, once where its converged steps are ({code}, {len(said)})")
        problems, n_sets, n_values = same_med(saved, out_dir / f"{name}_converged.rmed", field_scale=True)
        for p in problems[:10]:
            print("  " + p)
        check(not problems and n_values > 0,
              f"{name}, {ranks} ranks: the converged steps equal the serial ones ({n_sets} datasets/attributes, "
              f"{n_values} floats)")

    # Refused in parts, or wrong, said once with the deck's status: a solver of one process asked for
    # (ssnp121d_discrete.lua as written), LDLT_SP, and a relation's node name no part holds.
    cases = [
        ("ssnp121d_discrete", r"STAT_NON_LINE: on a mesh in parts MUMPS or PETSc solves"),
        ("petsc_solvers", r"STAT_NON_LINE: PRE_COND='LDLT_SP' is not available on a mesh in parts"),
        ("errors/parts_liaison_unknown_node", r"parts_liaison_unknown_node\.lua:12: AFFE_CHAR_MECA: LIAISON_DDL\[2\]"
                                              r"\.NOEUD: expected a node name of the mesh, got 'N99999'"),
        # VERI_NORM: a pressure group's inward and outward cells counted over the parts, as serially
        ("errors/veri_norm_parts", r"veri_norm_parts\.lua:16: AFFE_CHAR_MECA: PRES_REP\[1\]\.GROUP_MA: .* got group "
                                   r"'ENDS': 96 of 192 cells point into their body \(M2, M5, M7, \.\.\.\), 96 out of it"),
    ]
    for name, says in cases:
        text = (source / "testcases" / f"{name}.lua").read_text()
        path = parts / "testcases" / f"{name}.lua"
        path.parent.mkdir(exist_ok=True)
        if "PARTITIONNEUR" not in text:
            text = re.sub(r"LIRE_MAILLAGE\s*\{", "LIRE_MAILLAGE{ PARTITIONNEUR = 'PTSCOTCH',", text)
        path.write_text(text)
        for ranks in case_ranks(full):
            code, out, err, _ = run([mpirun(), "-np", ranks, exe, "run", path, "--out",
                                     scratch / f"{path.stem}{ranks}"], path.parent, timeout=120)
            lines = [l for l in err.splitlines() if re.search(says, l)]
            check(code == 2 and len(lines) == 1,
                  f"{name}, {ranks} ranks: exit 2 and the refusal once ({code}, {len(lines)}: {err.strip()[-300:]})")


# ---------------------------------------------------------------------------------------------
def expectations(deck):
    text = Path(deck).read_text()
    patterns = re.findall(r"^-- EXPECT_ERROR: *(.*)$", text, re.M)
    status = re.search(r"^-- EXPECT_STATUS: *(\d+)", text, re.M)
    return patterns, int(status.group(1)) if status else None


def errors(exe, source, scratch):
    scratch.mkdir(parents=True)
    # A launcher that does not end by itself past the time limit: verify asks it to (SIGTERM;
    # a real mpirun then ends its ranks) and reports TIMEOUT. The stand-in only waits (6 s): it
    # runs beside the rest of this test and is checked at the end.
    fake = scratch / "fake-launcher"
    fake.mkdir()
    (fake / "mpirun").write_text("#!/bin/bash\ntrap 'echo \"launcher: SIGTERM\"; kill $child; exit 143' TERM\n"
                                 "sleep 60 & child=$!\nwait\n")
    (fake / "mpirun").chmod(0o755)
    env = dict(ENV, PATH=f"{fake}:{ENV.get('PATH', '')}")
    launcher = WAITERS.submit(run, [exe, "verify", source / "testcases" / "patch_2d.lua", "--np", "2", "--time-limit",
                                    "1", "--out", "f"], scratch, env=env)
    errors_dir = source / "testcases" / "errors"
    for folder, deck, want in ((errors_dir, "misspelt_keyword.lua", 2), (errors_dir, "singular_free_body_mumps.lua", 3),
                               (errors_dir, "singular_free_direction_mumps.lua", 3)):
        path = folder / deck
        patterns, status = expectations(path)
        check(status == want, f"{deck}: the deck expects exit status {want}")
        logs = scratch / f"{path.stem}.logs"
        code, out, err, _ = run([mpirun(), "--output-filename", logs, "-np", 2, exe, "run", path, "--out", "o"], scratch)
        text = out + err
        check(code == want, f"{deck}: mpirun -np 2 exits {want}, as the serial run ({code})")
        for p in patterns:
            check(re.search(p, text) is not None, f"{deck}: output matches {p}")
        first = patterns[0]  # the line naming file:line: command
        check(len(re.findall(first, text)) == 1, f"{deck}: the error is printed once ({len(re.findall(first, text))})")
        check(re.search(re.escape(deck) + r":\d+: ", text) is not None, f"{deck}: the error names file:line")
        check(rank_output(logs, 1) == "", f"{deck}: rank 1 prints nothing")
        if "mumps" in deck:  # METHODE='MUMPS': the model is shared, the diagnosis is the serial one
            check("model shared among 2 ranks" in text, f"{deck}: the model is shared among the ranks")

    # RENUM='METIS' on a model shared among the ranks: rank 0 orders the gathered pattern.
    # MATR_DISTRIBUEE: 'OUI' (the default) shares the model, 'NON' gives every rank the whole system.
    code, out, err, _ = run([mpirun(), "-np", 2, exe, "run", HERE / "matr_distribuee.lua", "--out", "shared"], scratch)
    text = out + err
    check(code == 0 and "4 check(s) OK, 0 NOOK" in text and text.count("model shared among 2 ranks") == 1
          and "MUMPS ordering: METIS" in text and text.count("model whole on each of the 2 ranks, as asked") == 1,
          f"matr_distribuee.lua: one solve shared among the ranks with METIS's order, one whole on each, both exact "
          f"(exit {code})")

    code, out, err, _ = run([mpirun(), "-np", 2, exe, "verify", source / "testcases" / "patch_2d.lua"], scratch)
    check(code == 2 and (out + err).count("lunaster verify --np N") == 1,
          f"verify under mpirun refuses once, pointing at --np (exit {code})")
    env = dict(ENV, PATH=str(scratch / "empty-path"))
    code, out, err, _ = run([exe, "verify", source / "testcases" / "patch_2d.lua", "--np", "2"], scratch, env=env)
    check(code == 2 and "no mpirun on the PATH" in out + err, f"verify --np 2 without mpirun says so (exit {code})")
    code, out, err, _ = run([exe, "verify", source / "testcases" / "patch_2d.lua", "--np", "0"], scratch)
    check(code == 2 and "--np expects a positive number" in out + err, f"verify --np 0 is refused (exit {code})")

    # Budgets under verify --np 2: the ranks stop themselves, mpirun passes their status on. A
    # limit of LOOP_LIMIT s (4, 10 in a sanitizer build), not the loop's own 1 s: verify ends a run
    # still going 5 s past its limit, counted from mpirun's start, and the start of mpirun and its
    # ranks on a loaded machine must not decide whether the ranks get to stop themselves.
    report = scratch / "budgets.json"
    code, out, err, seconds = run([exe, "verify", HERE.parent / "budget" / "loop_forever.lua",
                                   HERE.parent / "budget" / "grow_forever.lua", "--np", "2", "-j", "2", "--out", "b",
                                   "--time-limit", str(LOOP_LIMIT), "--json", report], scratch)
    statuses = {Path(d["deck"]).name: d for d in json.loads(report.read_text())["decks"]}
    check(code == 1 and statuses["loop_forever.lua"]["status"] == "TIMEOUT"
          and statuses["grow_forever.lua"]["status"] == "OUT_OF_MEMORY",
          f"verify --np 2: TIMEOUT and OUT_OF_MEMORY as serially (exit {code}, {seconds:.1f} s)")
    check(statuses["loop_forever.lua"]["output"].count(f"loop_forever.lua:7: time limit of {LOOP_LIMIT} s exceeded") == 1,
          "verify --np 2: the deck line of the time limit, once")

    code, out, err, seconds = launcher.result()
    check(code == 1 and "launcher: SIGTERM" in out and re.search(r"patch_2d\.lua +TIMEOUT", out) is not None
          and 5.5 < seconds, f"verify --np: a launcher still running 5 s past the limit gets SIGTERM ({seconds:.1f} s)")


# ---------------------------------------------------------------------------------------------
def rank_failure(exe, meshgen, source, scratch):
    scratch.mkdir(parents=True)
    # A deck error on one rank while the other waits for it in MUMPS: the failing rank waits
    # RANK_WAIT_SECONDS for the others at the end of its run, then aborts the run with its status.
    # Those two runs mostly wait (the waiting ranks yield their core): they run beside the time
    # and memory limits below, not after them, and are checked at the end.
    error_deck = source / "testcases" / "errors" / "misspelt_keyword.lua"
    good_deck = source / "testcases" / "ssnp121a.lua"
    # Each mpirun at once has a session directory of its own (see main).
    waiting, sessions = {}, []
    for failing in (0, 1):
        args = [["run", good_deck, "--out", f"o{failing}"], ["run", good_deck, "--out", f"o{failing}"]]
        args[failing][1] = error_deck
        sessions.append(tempfile.mkdtemp(prefix="lunaster-ompi-"))
        env = dict(ENV, OMPI_MCA_orte_tmpdir_base=sessions[-1])
        waiting[failing] = WAITERS.submit(run, mpmd(exe, args[0], args[1], scratch / f"alone{failing}.logs"), scratch,
                                          env=env, timeout=120)

    deck = scratch / "refined.lua"  # about 3.6 s and 590 MB serially; MUMPS (collective) for its contact system
    shutil.copy(source / "tests" / "bench" / "ssnp121i_refined.lua", deck)
    # Refinement 5, as budget.long_solve: at 4 the solve ends within about a second since its
    # re-pairing pass needs no solve, and a 1 s limit could fall after it.
    subprocess.run([meshgen, "--v1", "hexa8:5x5x1", "--v2", "hexa20:4x4x1", "--refine", "5", "-o", scratch / "refined.med"],
                   check=True, stdout=subprocess.DEVNULL)
    # A limit that the set-up fits in and the solve does not, whatever the load: under mpirun it
    # counts from the deck's start (not the processes' start-up), the set-up (reading the mesh:
    # a fraction of a second, one to four in a sanitizer build on a loaded machine) fits in it
    # many times over, and the solve, given 200 steps instead of 1 (each step after the first about
    # 0.15 s of CPU serially: 1.96 s user for the deck with 1 step, 2.26 s with 3, /usr/bin/time),
    # takes half a minute of CPU, so it cannot end within the limit however fast the machine.
    text = deck.read_text()
    assert "INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 }" in text
    deck.write_text(text.replace("INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 1 }", "INTERVALLE = _F{ JUSQU_A = 1.0, NOMBRE = 200 }"))
    limit = 30 if SANITIZED else 5
    stop = (rf"refined\.lua: time limit of {limit} s exceeded while running \S*refined\.lua:\d+: STAT_NON_LINE; "
            r"the run is stopped")
    code, out, err, seconds = run([mpirun(), "-np", 2, exe, "run", deck, "-q", "--out", "o", "--time-limit", limit],
                                  scratch)
    check(code == 5 and seconds >= limit,
          f"--time-limit {limit} on both ranks stops the run: exit 5, not before the limit ({seconds:.1f} s)")
    check(len(re.findall(stop, out + err)) == 1 and "rank 1" not in out + err,
          "the time-limit message once, rank 0's")

    # The deck's set-up fits in the limit and its solve does not; AddressSanitizer's shadow
    # memory puts a process at about 200 MB before its first command (make test-asan).
    limit = "400" if SANITIZED else "150"
    memory = rf"memory limit of {limit} MB exceeded \(resident memory \d+ MB\) while running"
    for failing in (0, 1):
        args = [["run", deck, "-q", "--out", "o"], ["run", deck, "-q", "--out", "o"]]
        args[failing] += ["--memory-limit", limit]
        code, out, err, seconds = run(mpmd(exe, args[0], args[1], scratch / f"memory{failing}.logs"), scratch)
        check(code == 6,
              f"--memory-limit {limit} on rank {failing} only: that rank stops, and the run with it: exit 6 ({seconds:.1f} s)")
        check(re.search(memory, out + err) is not None and ((f"lunaster: rank {failing}:" in out + err) == (failing > 0)),
              f"the memory message is printed (by rank {failing}{', which says so' if failing else ''})")

    for failing in (0, 1):
        code, out, err, seconds = waiting[failing].result()
        shutil.rmtree(sessions[failing], ignore_errors=True)
        text = out + err
        check(code == 2 and RANK_WAIT_SECONDS - 1 < seconds,
              f"a deck error on rank {failing} alone ends the run: exit 2 after the wait ({seconds:.1f} s)")
        check("misspelt_keyword.lua:6: DEFI_MATERIAU: ELAS.NUU" in text, "the error is shown")
        check(f"rank {failing} stopped with exit status 2 and the other ranks have not ended" in text,
              "the abort says which rank stopped the run and why")
        if failing:
            check("lunaster: rank 1: " in text, "rank 1, silent until then, shows its error as it aborts the run")

    # Rank 1 fails alone and rank 0 ends its deck (no collective call on its way): every rank
    # returns the worst status, and rank 0 shows rank 1's error.
    code, out, err, seconds = run(mpmd(exe, ["run", source / "testcases" / "patch_2d.lua", "--out", "o", "-q"],
                                       ["run", error_deck, "--out", "o"], scratch / "worst.logs"), scratch)
    text = out + err
    # Without the wait: rank 0 ended (no rank was left to abort), whatever the time it took.
    check(code == 2 and "the other ranks have not ended" not in text,
          f"rank 0 OK, rank 1 deck error: the run exits 2, without the abort ({seconds:.1f} s)")
    check("lunaster: rank 1 ended with exit status 2 (rank 0: 0)" in text and
          "lunaster: rank 1: " + str(error_deck) + ":6: DEFI_MATERIAU: ELAS.NUU" in text,
          "rank 0 names the rank that ended otherwise, with its error")


def main():
    case = sys.argv[1]
    exe, meshgen, source, scratch = (Path(a).resolve() for a in sys.argv[2:6])
    full = sys.argv[6:] == ["full"]
    if sys.argv[6:] and not full:
        sys.exit(f"expected 'full' or nothing after the scratch folder, got {sys.argv[6:]}")
    shutil.rmtree(scratch, ignore_errors=True)
    # A session directory tree of its own for every mpirun of this case: concurrent OpenMPI
    # jobs of one user share /tmp/ompi.<host>.<uid>, which the last one to end removes while
    # another may be creating its directory in it. Short (its sockets' paths are limited).
    session = Path(tempfile.mkdtemp(prefix="lunaster-ompi-"))
    ENV["OMPI_MCA_orte_tmpdir_base"] = str(session)
    start = time.monotonic()
    try:
        if case == "verify_suite":
            verify_suite(exe, source, scratch, full)
        elif case == "shared_suite":
            shared_suite(exe, source, scratch, full)
        elif case == "outputs":
            outputs(exe, source, scratch)
        elif case == "errors":
            errors(exe, source, scratch)
        elif case == "parts_suite":
            parts_suite(exe, source, scratch, full)
        elif case == "contact_parts_suite":
            contact_parts_suite(exe, source, scratch, full)
        elif case == "rank_failure":
            rank_failure(exe, meshgen, source, scratch)
        else:
            sys.exit(f"unknown case {case}")
    finally:
        shutil.rmtree(session, ignore_errors=True)
    print(f"{len(failures)} failure(s) in {time.monotonic() - start:.1f} s")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
