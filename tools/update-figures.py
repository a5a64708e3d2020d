#!/usr/bin/env python3
"""update-figures.py: rewrites the figures file from a test log.

The image tests hold their figures to tests/image/figures.txt
(tests/image/check-figures.sh, docs/testing.md "The figures file") and print
them as

    figures: NAME tol TOL within WITHIN silhouette SILHOUETTE

This script reads those lines from test logs (meson's
build/meson-logs/testlog.txt, `meson test -v` output, any text) and writes
the file for the commit that changes figures on purpose:

  - a test of the log with no line gets one;
  - a line whose figures the log measured otherwise takes them (the lowest
    over the logs, e.g. the normal and the ASan build's); a line with a
    margin of its own (an animated program, whose line holds the lowest
    figures measured) only when a figure fell below FIGURE - MARGIN, and
    never under --raise-only;
  - every line it adds or changes takes REASON; the others keep theirs;
  - lines of tests the log did not run are kept (remove a test's line by
    hand, as figures-names asks).

    tools/update-figures.py [--file FILE] [--reason TEXT] [--raise-only] [--dry-run] LOG...

--raise-only takes only figures above the file's (a fix that improved
tests); --dry-run prints the changes and writes nothing. Without --reason
nothing is written when a line would change. Exit 0 when written (or
nothing to do), 1 on a missing reason or unreadable input, 2 on bad usage.
"""
import argparse
import os
import re
import sys

FIG = re.compile(r'figures: (\S+) tol (\d+) within ([0-9.]+) silhouette ([0-9.]+)\s*$')
LINE = re.compile(r'^(\S+)\s+(\d+)\s+([0-9.]+)\s+([0-9.]+)\s+(\S+)\s+(.*\S)\s*$')


def key(name):
    base, _, frame = name.partition('/')
    return (base, int(frame) if frame else -1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument('--file', default=os.path.join(here, '..', 'tests', 'image', 'figures.txt'))
    ap.add_argument('--reason')
    ap.add_argument('--raise-only', action='store_true')
    ap.add_argument('--dry-run', action='store_true')
    ap.add_argument('logs', nargs='+')
    a = ap.parse_args()
    if a.reason is not None and not a.reason.strip():
        ap.error('--reason: empty')

    measured = {}
    for path in a.logs:
        try:
            with open(path, errors='replace') as f:
                for text in f:
                    m = FIG.search(text)
                    if not m:
                        continue
                    name, tol, w, s = m.group(1), int(m.group(2)), float(m.group(3)), float(m.group(4))
                    old = measured.get(name)
                    if old and old[0] == tol:
                        w, s = min(w, old[1]), min(s, old[2])
                    measured[name] = (tol, w, s)
        except OSError as e:
            print('update-figures: %s: %s' % (path, e.strerror), file=sys.stderr)
            return 1
    if not measured:
        print('update-figures: no "figures:" lines in %s' % ' '.join(a.logs), file=sys.stderr)
        return 1

    header, lines = [], {}
    try:
        with open(a.file) as f:
            for n, text in enumerate(f, 1):
                if not text.strip() or text.lstrip().startswith('#'):
                    if not lines:
                        header.append(text.rstrip('\n'))
                    continue
                m = LINE.match(text)
                if not m:
                    print('update-figures: %s:%d: malformed line' % (a.file, n), file=sys.stderr)
                    return 1
                lines[m.group(1)] = [int(m.group(2)), float(m.group(3)), float(m.group(4)),
                                     m.group(5), m.group(6)]
    except FileNotFoundError:
        pass

    changes = []
    for name, (tol, w, s) in sorted(measured.items(), key=lambda i: key(i[0])):
        old = lines.get(name)
        if old is None:
            changes.append('%s: added: tol %d within %.5f silhouette %.5f' % (name, tol, w, s))
            lines[name] = [tol, w, s, '-', None]
            continue
        otol, ow, os_, margin, _ = old
        if otol == tol:
            if a.raise_only:
                w, s = max(w, ow), max(s, os_)
            if margin != '-':
                m = float(margin)
                if a.raise_only or (w >= ow - m - 1e-9 and s >= os_ - m - 1e-9):
                    continue
                w, s = min(w, ow), min(s, os_)
            if round(w, 5) == round(ow, 5) and round(s, 5) == round(os_, 5):
                continue
        elif a.raise_only:
            continue
        changes.append('%s: tol %d within %.5f silhouette %.5f -> tol %d within %.5f silhouette %.5f'
                       % (name, otol, ow, os_, tol, w, s))
        lines[name] = [tol, w, s, margin, None]

    for c in changes:
        print(c)
    if not changes:
        print('update-figures: %s holds the figures of the log' % a.file)
        return 0
    if a.dry_run:
        return 0
    if a.reason is None:
        print('update-figures: %d line(s) would change: give --reason (why the figures moved)'
              % len(changes), file=sys.stderr)
        return 1
    tmp = a.file + '.tmp'
    with open(tmp, 'w') as f:
        for h in header:
            f.write(h + '\n')
        for name in sorted(lines, key=key):
            tol, w, s, margin, reason = lines[name]
            f.write('%s %d %.5f %.5f %s %s\n' % (name, tol, w, s, margin,
                                                  reason if reason is not None else a.reason.strip()))
    os.replace(tmp, a.file)
    print('update-figures: %s: %d line(s) changed' % (a.file, len(changes)))
    return 0


if __name__ == '__main__':
    sys.exit(main())
