#!/usr/bin/env python3
"""pty_run.py ERR_FILE CMD...: runs CMD with its stderr on a pseudo-terminal (stdout and stdin as given), copies
everything written to the terminal into ERR_FILE and exits with CMD's exit status. The e2e scripts use it to see
what a command shows a user at a terminal, which a pipe never shows."""
import os
import pty
import subprocess
import sys

master, slave = pty.openpty()
process = subprocess.Popen(sys.argv[2:], stderr=slave)
os.close(slave)
captured = b""
while True:
    try:
        chunk = os.read(master, 65536)
    except OSError:  # EIO: the terminal's last writer has exited
        break
    if not chunk:
        break
    captured += chunk
os.close(master)
with open(sys.argv[1], "wb") as out:
    out.write(captured)
sys.exit(process.wait())
