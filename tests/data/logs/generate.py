#!/usr/bin/python3
"""Writes the Hall-log corpus of this folder from two simulated runs of the paper's rig with a
plate of rigid foam (mu_k 1.7 in the paper's Table I: T = 0.3016 s, so a few seconds hold enough
periods), sampled at 500 Hz for 3 s:

  frictionlab run scenes/paper-rig.yaml --set friction.mu_k=rigid-foam \
      --set sensor.sample_rate=500Hz --duration 3s --out END
  (the same with sensor.position [84 mm, 0 mm, 22 mm]: the sensor at the middle of the travel)

clean.csv is END/hall.csv as written; every other log is clean.csv (or the middle-of-travel run's
hall.csv, for mid-travel.csv) rewritten as a logger, a serial monitor or a spreadsheet writes it.
Usage: generate.py [MID_TRAVEL_HALL_CSV]   (run in this folder; deterministic)."""

import random
import sys

random.seed(20240607)


def samples(path):
    with open(path) as f:
        lines = f.read().splitlines()
    assert lines[0] == "t_us,adc"
    return [tuple(int(x) for x in l.split(",")) for l in lines[1:]]


S = samples("clean.csv")
BANNER = ("# frictionlab rig firmware 1: sample_hz=500 sample_us=2000.0000 raw_every=1 "
          "spacing_m=0.0890 spacing_err_m=0.0020 gravity=9.810 geometry=auto")


def write(name, text, mode="w", encoding="utf-8"):
    if mode == "wb":
        with open(name, "wb") as f:
            f.write(text)
        return
    with open(name, mode, encoding=encoding, newline="") as f:
        f.write(text)


def csv(rows, header="t_us,adc", end="\n"):
    return header + end + "".join(f"{t},{v}{end}" for t, v in rows)


# The rig firmware's own capture: its banner, comment lines between the samples, CRLF.
lines = [BANNER, "t_us,adc"]
for i, (t, v) in enumerate(S):
    lines.append(f"{t},{v}")
    if i == 300:
        lines.append("# signal learned: baseline=512.4 polarity=+1 timing_level=601.0")
write("firmware-capture.csv", "\r\n".join(lines) + "\r\n")

# arduino-cli monitor without --quiet: its banner, then the bytes the Uno's reset leaves, then
# the firmware's output.
write("arduino-cli-banner.csv",
      ("Monitor port settings:\n  baudrate=250000\n"
       "Connecting to /dev/ttyACM0. Press CTRL-C to exit.\n").encode() +
      b"\x00\xf8\xff\x80\xfe" + b"\r\n" + ("\r\n".join(lines) + "\r\n").encode(), mode="wb",
      encoding=None)

# A spreadsheet's "CSV UTF-8": a byte-order mark, CRLF.
write("bom.csv", "\ufeff" + csv(S, end="\r\n"))

# The Arduino IDE's serial monitor with "Show timestamp", copied and pasted.
clock = 10 * 3600 + 41 * 60 + 7.0
out = []
for t, v in [(None, None)] + S:
    stamp = clock + (0 if t is None else t * 1e-6) + 0.004 * random.random()
    h, rest = divmod(stamp, 3600)
    m, sec = divmod(rest, 60)
    prefix = f"{int(h):02d}:{int(m):02d}:{sec:06.3f} -> "
    out.append(prefix + ("t_us,adc" if t is None else f"{t},{v}"))
write("ide-timestamps.txt", "\n".join(out) + "\n")

# A German spreadsheet: semicolons, seconds with a decimal comma.
write("decimal-comma-semicolon.csv",
      "Time [s];ADC Value\n" + "".join(f"{t * 1e-6:.6f};{v}\n".replace(".", ",") for t, v in S))

# A spreadsheet's "Unicode text": UTF-16 with a byte-order mark, tabs, a decimal comma.
write("utf16-tab.txt",
      "time_s\tvalue\r\n" + "".join(f"{t * 1e-6:.6f}\t{v}\r\n".replace(".", ",") for t, v in S),
      encoding="utf-16")

# A sketch printing micros() and analogRead(A0), no header.
write("no-header.csv", "".join(f"{t},{v}\n" for t, v in S))

# A sketch printing analogRead(A0) only, with a header: the time comes from --rate 500Hz.
write("no-time-column.csv", "sensorValue\n" + "".join(f"{v}\n" for _, v in S))

# Arduino-style names, millis() (the samples are 2 ms apart: whole milliseconds).
write("millis-sensorvalue.csv",
      "millis(),sensorValue\n" + "".join(f"{t // 1000},{v}\n" for t, v in S))

# millis() read twice in one millisecond: a repeated time on 5 lines, each followed by the
# sample it should have been. The repeated line's value is the previous sample's.
rows = []
repeat_at = sorted(random.sample(range(100, len(S) - 1), 5))
for i, (t, v) in enumerate(S):
    rows.append(f"{t},{v}")
    if i in repeat_at:
        rows.append(f"{t},{v}")
write("repeated-time.csv", "t_us,adc\n" + "\n".join(rows) + "\n")

# Lines corrupted in transit: bytes garbled, a newline lost (two lines run together), a line cut.
rows = []
corrupt_at = sorted(random.sample(range(100, len(S) - 1), 6))
for i, (t, v) in enumerate(S):
    line = f"{t},{v}"
    k = corrupt_at.index(i) if i in corrupt_at else -1
    if k in (0, 3):
        line = f"{t},\x8f{v}\xfe"            # garbled bytes in the value
    elif k == 1:
        line = f"{t},{v}{S[i + 1][0]},{S[i + 1][1]}"  # the newline lost: two samples in one
    elif k == 2:
        line = f"{t}"                        # cut after the time
    elif k in (4, 5):
        line = f"{t}\x00{v}"                 # a NUL for the comma
    rows.append(line)
write("corrupted-line.csv", ("t_us,adc\n" + "\n".join(rows) + "\n").encode("latin-1"), mode="wb",
      encoding=None)

# A capture at the wrong baud rate for a third of the time: mostly garbage.
rows = []
for i, (t, v) in enumerate(S):
    if 500 <= i < 1000:
        rows.append("".join(chr(random.choice([0x3f, 0xe0, 0xf8, 0x80, 0x9c, 0x30, 0x2c]))
                            for _ in range(random.randint(4, 12))))
    else:
        rows.append(f"{t},{v}")
write("mostly-garbage.csv", ("t_us,adc\n" + "\n".join(rows) + "\n").encode("latin-1"), mode="wb",
      encoding=None)

# The board reset after 0.4 s (the port opened again): the firmware's banner and header again,
# in the middle of a line, and the clock from 0.
first = S[:200]
lines = [BANNER, "t_us,adc"] + [f"{t},{v}" for t, v in first]
text = "\n".join(lines) + "\n" + "31" + "\n".join([BANNER, "t_us,adc"] +
                                                   [f"{t},{v}" for t, v in S]) + "\n"
write("board-restarted.csv", text)

# The sensor at the middle of the travel: two passes per period, evenly spaced.
if len(sys.argv) > 1:
    M = samples(sys.argv[1])
    write("mid-travel.csv", csv(M))
