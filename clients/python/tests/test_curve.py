"""CURVE on the client side against a pure-Python CURVE server (integration: loopback sockets).

The C++ server's CURVE support is another branch's work; this server follows its conventions
(certificates as zmq.auth writes them, clients allowed by their public key files in one folder,
checked by ZAP through zmq.auth.thread.ThreadAuthenticator), so the clients meet what it will do.
"""

import os
import shutil
import tempfile
import threading
import time
import unittest

import zmq
import zmq.auth
from zmq.auth.thread import ThreadAuthenticator
from zmq.utils.monitor import recv_monitor_message

from sph_client import ControlClient, CurveConfigError, FrameSubscriber, GazePublisher, pb

from .frame_factory import make_frame

WAIT_S = 30.0


def make_certificates(folder):
    """server, client and intruder certificates; only the client's public key is allowed."""
    keys = os.path.join(folder, "keys")
    allowed = os.path.join(folder, "allowed")
    os.makedirs(keys)
    os.makedirs(allowed)
    for name, role in (("server", "server"), ("client", "client"), ("intruder", "client")):
        zmq.auth.create_certificates(keys, name, metadata={"name": name, "role": role})
    shutil.copy(os.path.join(keys, "client.key"), allowed)
    return keys, allowed


class CurveServer(threading.Thread):
    """Frames out on PUB, gaze in on SUB, control on ROUTER: all CURVE servers, one thread."""

    def __init__(self, keys, allowed):
        super().__init__(daemon=True)
        self.context = zmq.Context()
        self.auth = ThreadAuthenticator(self.context)
        self.auth.start()
        self.auth.configure_curve(domain="*", location=allowed)
        public, secret = zmq.auth.load_certificate(os.path.join(keys, "server.key_secret"))
        self.sockets = {}
        for name, kind in (("frames", zmq.PUB), ("gaze", zmq.SUB), ("control", zmq.ROUTER)):
            s = self.context.socket(kind)
            s.linger = 0
            s.curve_secretkey, s.curve_publickey, s.curve_server = secret, public, True
            if kind == zmq.SUB:
                s.setsockopt(zmq.SUBSCRIBE, b"")
            s.bind("tcp://127.0.0.1:*")
            self.sockets[name] = s
        self.endpoints = {k: s.getsockopt_string(zmq.LAST_ENDPOINT) for k, s in self.sockets.items()}
        self.gaze_received = []
        self.control_users = []  # ZAP User-Id (the client's public key) of each request
        self.stop = threading.Event()
        self.error = None

    def run(self):
        try:
            poller = zmq.Poller()
            poller.register(self.sockets["gaze"], zmq.POLLIN)
            poller.register(self.sockets["control"], zmq.POLLIN)
            frame = make_frame([[0.1, 0.2, 0.3]], [1])
            while not self.stop.is_set():
                frame.sequence += 1
                self.sockets["frames"].send(frame.SerializeToString())
                for socket, _ in poller.poll(20):
                    if socket is self.sockets["gaze"]:
                        sample = pb.GazeSample()
                        sample.ParseFromString(socket.recv())
                        self.gaze_received.append(sample)
                    else:
                        identity, payload = socket.recv_multipart(copy=False)
                        self.control_users.append(payload.get("User-Id"))
                        request = pb.Control()
                        request.ParseFromString(payload.bytes)
                        reply = pb.ControlReply(protocol_version=1, request_id=request.request_id, ok=True)
                        reply.status.scene = "curve-test"
                        socket.send_multipart([identity.bytes, reply.SerializeToString()])
        except Exception as error:  # surfaced by the test, not lost in a thread
            self.error = error

    def close(self):
        self.stop.set()
        self.join(10)
        self.auth.stop()
        self.context.destroy(linger=0)


def wait_for_event(socket, wanted, timeout_s=WAIT_S):
    """The first of the `wanted` monitor events on `socket`, or None by the deadline."""
    monitor = socket.get_monitor_socket()
    try:
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            if monitor.poll(100):
                event = recv_monitor_message(monitor)["event"]
                if event in wanted:
                    return event
        return None
    finally:
        socket.disable_monitor()
        monitor.close(linger=0)


class Curve(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="sph_curve_")
        self.keys, allowed = make_certificates(self.folder)
        self.server = CurveServer(self.keys, allowed)
        self.server.start()
        self.context = zmq.Context()

    def tearDown(self):
        self.context.destroy(linger=0)
        self.server.close()
        shutil.rmtree(self.folder, ignore_errors=True)
        self.assertIsNone(self.server.error)

    def key(self, name, secret=False):
        return os.path.join(self.keys, f"{name}.key_secret" if secret else f"{name}.key")

    def client_keys(self, name="client"):
        return {"curve_secret": self.key(name, secret=True), "curve_server": self.key("server")}

    def test_frames_reach_an_allowed_subscriber(self):
        with FrameSubscriber(self.server.endpoints["frames"], context=self.context, **self.client_keys()) as sub:
            frame = sub.recv(timeout_s=WAIT_S)
        self.assertIsNotNone(frame)
        self.assertEqual(frame.positions.shape, (1, 3))

    def test_gaze_reaches_the_server(self):
        with GazePublisher(self.server.endpoints["gaze"], source_id="curve", context=self.context,
                           **self.client_keys()) as gaze:
            self.assertTrue(gaze.wait_connected(WAIT_S))
            deadline = time.monotonic() + WAIT_S
            # A PUB drops until the SUB's subscription has arrived: send until one gets through.
            while not self.server.gaze_received and time.monotonic() < deadline:
                gaze.send(0.5, 0.5)
                time.sleep(0.02)
        self.assertTrue(self.server.gaze_received)
        self.assertEqual(self.server.gaze_received[0].source_id, "curve")

    def test_control_round_trip_carries_the_clients_key(self):
        with ControlClient(self.server.endpoints["control"], context=self.context, timeout_s=WAIT_S,
                           **self.client_keys()) as control:
            reply = control.status()
        self.assertEqual(reply.status.scene, "curve-test")
        client_public, _ = zmq.auth.load_certificate(self.key("client"))
        self.assertEqual(self.server.control_users, [client_public.decode()])

    def test_a_key_the_server_does_not_know_is_refused(self):
        sub = FrameSubscriber(self.server.endpoints["frames"], context=self.context, **self.client_keys("intruder"))
        try:
            # ZAP says no: the handshake fails with an authentication error (ZMTP 3.1 reports it).
            event = wait_for_event(sub.socket, {zmq.EVENT_HANDSHAKE_FAILED_AUTH, zmq.EVENT_HANDSHAKE_SUCCEEDED})
            self.assertEqual(event, zmq.EVENT_HANDSHAKE_FAILED_AUTH)
        finally:
            sub.close()

    def test_a_plain_client_cannot_talk_to_a_curve_server(self):
        sub = FrameSubscriber(self.server.endpoints["frames"], context=self.context)
        try:
            event = wait_for_event(sub.socket, {zmq.EVENT_HANDSHAKE_FAILED_PROTOCOL, zmq.EVENT_HANDSHAKE_SUCCEEDED,
                                                zmq.EVENT_HANDSHAKE_FAILED_NO_DETAIL})
            self.assertIn(event, {zmq.EVENT_HANDSHAKE_FAILED_PROTOCOL, zmq.EVENT_HANDSHAKE_FAILED_NO_DETAIL})
        finally:
            sub.close()


class CurveArguments(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="sph_curve_args_")
        self.keys, _ = make_certificates(self.folder)
        self.context = zmq.Context()

    def tearDown(self):
        self.context.destroy(linger=0)
        shutil.rmtree(self.folder, ignore_errors=True)

    def assertRefused(self, words, **kw):
        with self.assertRaises(CurveConfigError) as caught:
            FrameSubscriber("tcp://127.0.0.1:1", context=self.context, **kw)
        self.assertIn(words, str(caught.exception))

    def test_half_a_configuration_is_refused(self):
        self.assertRefused("both", curve_secret=os.path.join(self.keys, "client.key_secret"))
        self.assertRefused("both", curve_server=os.path.join(self.keys, "server.key"))

    def test_a_public_file_is_not_a_secret(self):
        self.assertRefused("no secret key", curve_secret=os.path.join(self.keys, "client.key"),
                           curve_server=os.path.join(self.keys, "server.key"))

    def test_a_missing_file_is_named(self):
        missing = os.path.join(self.keys, "nobody.key_secret")
        self.assertRefused("nobody.key_secret", curve_secret=missing, curve_server=os.path.join(self.keys, "server.key"))


if __name__ == "__main__":
    unittest.main()
