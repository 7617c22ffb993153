#!/usr/bin/env python3
"""A stand-in for the rig's Arduino on a pseudo-terminal, for the live rig's browser test.

    python3 tests/feed_rig.py HALL_CSV

Prints the pseudo-terminal's name (the port to give `frictionlab serve --serial`), then waits
for a line "go" on stdin and sends the firmware's banner, its header and the samples of
HALL_CSV (a run's `t_us,adc` file) in the firmware's format at real speed (each line when its
time comes), prints "sent" and waits for stdin to close, holding the port open.
"""
import os
import pty
import sys
import time
import tty


def main() -> int:
    rows = open(sys.argv[1], encoding="utf-8").read().splitlines()[1:]
    master, slave = pty.openpty()
    tty.setraw(slave)
    print(os.ttyname(slave), flush=True)
    if sys.stdin.readline().strip() != "go":
        return 1
    os.write(master, b"# frictionlab rig firmware 1: sample_hz=1000 sample_us=1000.0000 "
             b"raw_every=1\r\nt_us,adc\r\n")
    start = time.monotonic()
    sent = 0
    while sent < len(rows):
        now_us = (time.monotonic() - start) * 1e6
        chunk = []
        while sent < len(rows) and int(rows[sent].split(",")[0]) <= now_us:
            chunk.append(rows[sent])
            sent += 1
        if chunk:
            os.write(master, ("\r\n".join(chunk) + "\r\n").encode())
        time.sleep(0.005)
    print("sent", flush=True)
    sys.stdin.read()
    os.close(master)
    return 0


if __name__ == "__main__":
    sys.exit(main())
