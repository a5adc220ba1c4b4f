#!/usr/bin/env python3
"""Every command the README (and the docs pages it links) shows runs as written.

usage: run_readme_commands.py SOURCE_DIR BUILD_DIR SCRATCH_DIR

Each line of a ```sh block of README.md and of the pages in PAGES is one command (a line ending in
a backslash continues on the next). They run in the order written, page by page, with bash, from
a scratch copy of testcases/ in which build/ points at BUILD_DIR, as a user runs them from a fresh
clone (a command shown again on a later page is run once). A command passes on exit status 0, or
on the status its comment states ("# exits 2: ...").
The few that cannot run here are in SKIP by their exact text, each with its reason; a SKIP entry
that no page shows any more is an error, so the list cannot outlive its commands.

The README's first deck (the ```lua block after "Save this as `first_deck.lua`") must equal
testcases/first_deck.lua byte for byte; it is written to the scratch folder as first_deck.lua
before the README's commands run, as the guide tells the reader to do. No README section (a
heading and its text up to the next heading) may be longer than a screen, MAX_SECTION_LINES, and
every relative link of these pages must name a file of the repository.
"""
import difflib
import os
import re
import shutil
import subprocess
import sys
import time

PAGES = ['README.md', 'docs/running.md', 'docs/parallel.md', 'docs/solvers.md', 'docs/modelling.md',
         'docs/architecture.md', 'docs/study.md']
MAX_SECTION_LINES = 50
# Exact command text -> why it does not run here.
SKIP = {
    'make verify': 'it installs packages and builds what this test needs before it can run; '
                   'it then runs `lunaster verify testcases`, which this test runs as the README shows it',
    'make test': 'it is what runs this test (CTest label readme)',
    'build/lunaster verify testcases --np 2 --json r.json':
        'every deck on 2 ranks: CTest mpi.verify_suite runs `verify testcases --np 2 --json` and compares '
        'each value with the serial run',
    'build/lunaster verify testcases --np 2 --solveur=MUMPS':
        'every deck shared among 2 ranks: CTest mpi.shared_suite runs it on 2 and on 3 ranks',
    'mpirun -np 8 --hostfile hosts build/lunaster run /shared/model.lua':
        'needs several machines and a shared folder',
}
FIRST_DECK_INTRO = 'Save this as `first_deck.lua`'
COMMAND_TIMEOUT = 900  # seconds; `verify testcases` runs every deck


def sh_commands(path, text):
    """(line number, command, expected status) of each command of the page's ```sh blocks."""
    out, block, pending, start = [], None, '', 0
    for number, line in enumerate(text.split('\n'), 1):
        stripped = line.strip()
        if block is None:
            if stripped.startswith('```'):
                block = stripped[3:].strip()
            continue
        if stripped.startswith('```'):
            if pending:
                raise SystemExit(f'{path}:{start}: a command ends in a backslash at the end of its block')
            block = None
            continue
        if block != 'sh' or (not stripped and not pending) or (stripped.startswith('#') and not pending):
            continue
        if not pending:
            start = number
        if stripped.endswith('\\'):
            pending += stripped[:-1] + ' '
            continue
        command = (pending + stripped).strip()
        pending = ''
        comment = command.split(' # ', 1)[1] if ' # ' in command else ''
        status = re.search(r'\bexits? (\d+)\b', comment)
        out.append((start, command, int(status.group(1)) if status else 0))
    return out


def code_without_comment(command):
    return command.split(' # ', 1)[0].strip()


def lua_blocks(text):
    """(offset, content) of each ```lua block."""
    return [(m.start(), m.group(1)) for m in re.finditer(r'```lua\n(.*?)```', text, re.S)]


def check_first_deck(source, readme):
    deck = open(os.path.join(source, 'testcases', 'first_deck.lua')).read()
    intro = readme.find(FIRST_DECK_INTRO)
    if intro < 0:
        return None, [f'README.md: no "{FIRST_DECK_INTRO}" introducing the first deck']
    after = [content for start, content in lua_blocks(readme) if start > intro]
    if not after:
        return None, ['README.md: no ```lua block after the first deck\'s introduction']
    if after[0] != deck:
        diff = ''.join(difflib.unified_diff(deck.splitlines(True), after[0].splitlines(True),
                                            'testcases/first_deck.lua', 'README.md first deck'))
        return after[0], ['README.md: the first deck differs from testcases/first_deck.lua:\n' + diff]
    return after[0], []


def check_sections(readme):
    errors, heading, count, start = [], None, 0, 0
    in_code = False
    for number, line in enumerate(readme.split('\n') + ['# end'], 1):
        if line.startswith('```'):
            in_code = not in_code
        if line.startswith('#') and not in_code:
            if heading is not None and count > MAX_SECTION_LINES:
                errors.append(f'README.md:{start}: section "{heading}" is {count} lines long, '
                              f'more than a screen ({MAX_SECTION_LINES})')
            heading, count, start = line.lstrip('#').strip(), 0, number
        count += 1
    return errors


def check_links(source, page, text):
    errors = []
    for target in re.findall(r'\]\(([^)#\s]+)(?:#[^)]*)?\)', text):
        if re.match(r'[a-z]+:', target):
            continue
        if not os.path.exists(os.path.normpath(os.path.join(source, os.path.dirname(page), target))):
            errors.append(f'{page}: link to {target}: no such file')
    return errors


def main():
    source, build, scratch = (os.path.abspath(a) for a in sys.argv[1:4])
    texts = {page: open(os.path.join(source, page)).read() for page in PAGES}
    errors = check_sections(texts['README.md'])
    for page, text in texts.items():
        errors += check_links(source, page, text)
    deck, deck_errors = check_first_deck(source, texts['README.md'])
    errors += deck_errors

    shown = {code_without_comment(c) for page in PAGES for _, c, _ in sh_commands(page, texts[page])}
    for stale in sorted(set(SKIP) - shown):
        errors.append(f'SKIP lists "{stale}", which no page shows any more')

    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    shutil.copytree(os.path.join(source, 'testcases'), os.path.join(scratch, 'testcases'))
    os.symlink(build, os.path.join(scratch, 'build'))
    if deck is not None:
        with open(os.path.join(scratch, 'first_deck.lua'), 'w') as f:
            f.write(deck)
    env = dict(os.environ)
    # As docs/parallel.md says: OpenMPI refuses root unless told; the test may run as root.
    env.update(OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1',
               OMPI_MCA_rmaps_base_oversubscribe='1')

    ran, done = 0, {}
    for page in PAGES:
        for line, command, expected in sh_commands(page, texts[page]):
            code = code_without_comment(command)
            if code in SKIP:
                print(f'SKIP {page}:{line}: {code}  ({SKIP[code]})')
                continue
            if code in done:  # a page repeats a command run before: its status stands, reported there
                status, first, first_expected = done[code]
                print(f"{'OK' if status == expected else 'FAIL'} {page}:{line}: {code}  (exit {status}, "
                      f'expected {expected}: run at {first})')
                if status != expected and expected != first_expected:
                    errors.append(f'{page}:{line}: `{code}` exited {status}, the page says {expected}')
                continue
            began = time.monotonic()
            try:
                run = subprocess.run(['bash', '-c', command], cwd=scratch, env=env, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, timeout=COMMAND_TIMEOUT)
                status, output = run.returncode, run.stdout.decode(errors='replace')
            except subprocess.TimeoutExpired as e:
                status, output = 'timeout', (e.stdout or b'').decode(errors='replace')
            done[code] = (status, f'{page}:{line}', expected)
            ran += 1
            print(f"{'OK' if status == expected else 'FAIL'} {page}:{line}: {code}  (exit {status}, "
                  f'expected {expected}, {time.monotonic() - began:.1f} s)')
            if status != expected:
                tail = '\n'.join(output.rstrip().split('\n')[-25:])
                errors.append(f'{page}:{line}: `{code}` exited {status}, the page says {expected}; '
                              f'last lines:\n{tail}')
    print(f'{ran} distinct commands run, {len(SKIP)} skipped by name')
    for e in errors:
        print('ERROR ' + e)
    return 1 if errors else 0


if __name__ == '__main__':
    sys.exit(main())
