#!/usr/bin/python3
"""Subscription flood against a running sph_server, measured by hand, never in a test.

One XSUB peer sends COUNT distinct subscriptions of SIZE bytes to the frames socket, then leaves.
Prints the server's resident memory (from /proc/PID/status) before, during and after, the
subscriber count the server reports, and the longest gap in frames (a well-behaved subscriber) and
in control replies while the flooding peer leaves.

  build/bin/sph_server --scene dambreak --method gaze &
  /usr/bin/python3 scripts/flood_subscriptions.py --pid $! --count 300 --size 65000

Debian's python3-zmq (scripts/install_deps.sh); plain /usr/bin/python3, not a virtual environment.
"""
import argparse
import threading
import time

import zmq



def rss_mb(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return -1.0


def settle(pid, seconds):
    """RSS once it stops growing (or after `seconds`)."""
    end = time.time() + seconds
    last = rss_mb(pid)
    while time.time() < end:
        time.sleep(0.5)
        now = rss_mb(pid)
        if abs(now - last) < 1.0:
            return now
        last = now
    return last


def subscribers(ctx, control):
    """The server's subscriber count from a status request (protobuf-free: field 10 of ServerStatus)."""
    dealer = ctx.socket(zmq.DEALER)
    dealer.linger = 0
    dealer.connect(control)
    # Control{protocol_version: 1, request_id: 1, status: {}} by hand: 08 01 10 01 52 00.
    dealer.send(bytes([0x08, 0x01, 0x10, 0x01, 0x52, 0x00]))
    start = time.time()
    if not dealer.poll(30000):
        return None, time.time() - start
    reply = dealer.recv()
    elapsed = time.time() - start
    dealer.close()
    return parse_subscribers(reply), elapsed


def varint(data, i):
    shift = value = 0
    while True:
        b = data[i]
        i += 1
        value |= (b & 0x7F) << shift
        shift += 7
        if not b & 0x80:
            return value, i


def fields(data):
    i = 0
    while i < len(data):
        key, i = varint(data, i)
        number, wire = key >> 3, key & 7
        if wire == 0:
            value, i = varint(data, i)
        elif wire == 2:
            length, i = varint(data, i)
            value, i = data[i:i + length], i + length
        elif wire == 1:
            value, i = data[i:i + 8], i + 8
        elif wire == 5:
            value, i = data[i:i + 4], i + 4
        else:
            return
        yield number, value


def parse_subscribers(reply):
    for number, value in fields(reply):
        if number == 6:  # ControlReply.status
            for n, v in fields(value):
                if n == 10:
                    return v
            return 0
    return None


class FrameWatch(threading.Thread):
    """A well-behaved subscriber that records the longest gap between frames."""

    def __init__(self, ctx, endpoint):
        super().__init__(daemon=True)
        self.sub = ctx.socket(zmq.SUB)
        self.sub.linger = 0
        self.sub.setsockopt(zmq.SUBSCRIBE, b"")
        self.sub.connect(endpoint)
        self.stop = False
        self.frames = 0
        self.max_gap = 0.0
        self.watching = False

    def run(self):
        last = None
        while not self.stop:
            if self.sub.poll(100):
                self.sub.recv()
                now = time.time()
                if last is not None and self.watching:
                    self.max_gap = max(self.max_gap, now - last)
                last = now
                self.frames += 1


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--pid", type=int, required=True, help="sph_server's process id")
    p.add_argument("--frames", default="tcp://127.0.0.1:5555")
    p.add_argument("--control", default="tcp://127.0.0.1:5558")
    p.add_argument("--count", type=int, default=300)
    p.add_argument("--size", type=int, default=65000)
    p.add_argument("--settle", type=float, default=20.0, help="seconds to wait for memory to settle")
    a = p.parse_args()

    ctx = zmq.Context()
    watch = FrameWatch(ctx, a.frames)
    watch.start()
    time.sleep(1.0)
    print(f"before: {rss_mb(a.pid):.1f} MB, subscribers {subscribers(ctx, a.control)[0]}")

    flood = ctx.socket(zmq.XSUB)
    flood.linger = 0
    flood.sndhwm = 0
    flood.connect(a.frames)
    time.sleep(0.5)
    t0 = time.time()
    for i in range(a.count):
        topic = i.to_bytes(4, "little") * (a.size // 4 + 1)
        flood.send(b"\x01" + topic[: a.size])
    sent_s = time.time() - t0
    during = settle(a.pid, a.settle)
    count, _ = subscribers(ctx, a.control)
    print(f"after {a.count} x {a.size} B subscriptions ({sent_s:.1f} s to send): {during:.1f} MB, "
          f"subscribers {count}")

    watch.watching = True
    flood.close()
    count, reply_s = subscribers(ctx, a.control)
    time.sleep(3.0)
    after = settle(a.pid, a.settle)
    watch.stop = True
    watch.join()
    count_after, _ = subscribers(ctx, a.control)
    print(f"after the peer left: {after:.1f} MB, subscribers {count_after}, status reply {reply_s * 1e3:.0f} ms, "
          f"longest frame gap {watch.max_gap * 1e3:.0f} ms, {watch.frames} frames seen")
    ctx.destroy(linger=0)  # also closes the watcher's socket, which term() would wait for


if __name__ == "__main__":
    main()
