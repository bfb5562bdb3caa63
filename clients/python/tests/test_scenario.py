"""sph_load's scenario files, statistics, report and gaze patterns (unit: no sockets)."""

import json
import os
import tempfile
import unittest

from sph_client import gaze_patterns
from sph_client.load.records import PhaseRecord, SentTimes, SubscriberRecord
from sph_client.load.report import merge, summarize
from sph_client.load.scenario import ScenarioError, load_scenario, scenario_from_dict, single_phase
from sph_client.load.stats import Samples, distribution, percentile, step_rate

HERE = os.path.dirname(os.path.abspath(__file__))


class Scenarios(unittest.TestCase):
    def test_phases_take_defaults_and_names(self):
        s = scenario_from_dict({"phases": [{"duration_s": 2}, {"duration_s": 3, "subscribers": 4,
                                                                "gaze_publishers": 2, "gaze_hz": 200}]})
        self.assertEqual(s.duration_s, 5)
        self.assertEqual([p.name for p in s.phases], ["phase1", "phase2"])
        self.assertEqual(s.phases[0].subscribers, 1)
        self.assertEqual(s.max_of("gaze_publishers"), 2)
        self.assertEqual(s.phases[1].control_verbs, ["status"])

    def test_shipped_scenarios_load(self):
        folder = os.path.join(HERE, "..", "scenarios")
        names = sorted(f for f in os.listdir(folder) if f.endswith(".json"))
        self.assertTrue(names)
        for name in names:
            with self.subTest(name=name):
                self.assertTrue(load_scenario(os.path.join(folder, name)).phases)

    def test_refusals_name_the_place(self):
        cases = [
            ({}, "'phases'"),
            ({"phases": []}, "'phases'"),
            ({"phases": [{"duration": 5}]}, "unknown keys: duration"),
            ({"phases": [{"subscribers": -1}]}, "phases[0].subscribers"),
            ({"phases": [{"subscribers": 1.5}]}, "phases[0].subscribers"),
            ({"phases": [{"duration_s": 0}]}, "phases[0].duration_s"),
            ({"phases": [{"gaze_pattern": "zigzag"}]}, "gaze_pattern"),
            ({"phases": [{"gaze_publishers": 1, "gaze_hz": 0}]}, "gaze_hz > 0"),
            ({"phases": [{"control_verbs": ["explode"]}]}, "explode"),
            ({"phases": [{"control_verbs": [{"verb": "load_scene"}]}]}, "load_scene"),
            ({"phases": [{}], "extra": 1}, "unknown scenario keys: extra"),
            ({"phases": [{"duration_s": 86400}, {"duration_s": 10}]}, "more than"),
        ]
        for data, words in cases:
            with self.subTest(data=data):
                with self.assertRaises(ScenarioError) as caught:
                    scenario_from_dict(data)
                self.assertIn(words, str(caught.exception))

    def test_file_errors_are_scenario_errors(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "bad.json")
            with open(path, "w") as f:
                f.write("{not json")
            with self.assertRaises(ScenarioError):
                load_scenario(path)
            with self.assertRaises(ScenarioError):
                load_scenario(os.path.join(d, "missing.json"))

    def test_command_line_is_one_phase(self):
        s = single_phase(duration_s=3, subscribers=8, gaze_publishers=2, gaze_hz=200, pose_hz=60)
        self.assertEqual(len(s.phases), 1)
        self.assertEqual(s.phases[0].pose_hz, 60)
        json.dumps(s.to_json())


class Statistics(unittest.TestCase):
    def test_nearest_rank_percentiles(self):
        values = list(range(1, 101))
        self.assertEqual(percentile(values, 50), 50)
        self.assertEqual(percentile(values, 99), 99)
        self.assertEqual(percentile(values, 100), 100)
        self.assertEqual(percentile([7.0], 99), 7.0)
        self.assertIsNone(percentile([], 50))
        d = distribution([3, 1, 2])
        self.assertEqual((d["count"], d["min"], d["p50"], d["max"]), (3, 1, 2, 3))

    def test_step_rate_over_the_servers_clock_skips_resets(self):
        # 100 steps/s for 1 s, a reset to 0, then 100 steps/s for another second.
        obs = [(i * 10_000, i) for i in range(101)] + [(1_010_000 + i * 10_000, i) for i in range(101)]
        self.assertAlmostEqual(step_rate(obs), 100.0)
        self.assertIsNone(step_rate([(0, 5)]))


class BoundedMemory(unittest.TestCase):
    def test_samples_keep_exact_extremes_and_close_percentiles_past_their_capacity(self):
        samples = Samples(capacity=1000)
        for v in range(100_000):
            samples.append(float(v))
        self.assertEqual(len(samples.reservoir), 1000)
        d = distribution(samples)
        self.assertEqual((d["count"], d["min"], d["max"]), (100_000, 0.0, 99_999.0))
        self.assertAlmostEqual(d["p50"], 50_000, delta=5_000)
        self.assertGreater(d["p99"], 95_000)

    def test_sent_times_forget_the_oldest(self):
        times = SentTimes(keep=4)
        for sequence in range(1, 11):
            times.append(sequence * 100)
        self.assertEqual(times.get(10), 1000)
        self.assertEqual(times.get(7), 700)
        self.assertIsNone(times.get(6))
        self.assertIsNone(times.get(11))
        self.assertIsNone(times.get(0))


class Summary(unittest.TestCase):
    def test_a_silent_subscriber_still_shows(self):
        record = PhaseRecord()
        record.subscribers[0] = SubscriberRecord(frames=10, gaps=1, missed=2, lag_ms=Samples([1.0, 2.0]))
        s = summarize(record, 2.0, subscribers=3, gaze_publishers=1)
        self.assertEqual([x["frames"] for x in s["subscribers"]], [10, 0, 0])
        self.assertFalse(s["subscriber_totals"]["every_subscriber_received_frames"])
        self.assertEqual(s["subscriber_totals"]["missed"], 2)
        self.assertEqual(s["gaze"]["sent_per_publisher"], [0])
        json.dumps(s)

    def test_merge_adds_phases(self):
        a, b = PhaseRecord(), PhaseRecord()
        a.subscribers[0] = SubscriberRecord(frames=5)
        b.subscribers[0] = SubscriberRecord(frames=7)
        a.gaze_sent[0], b.gaze_sent[0] = 10, 20
        a.control_rtt_ms, b.control_rtt_ms = Samples([1.0]), Samples([2.0, 3.0])
        total = merge([a, b])
        self.assertEqual(total.subscribers[0].frames, 12)
        self.assertEqual(total.gaze_sent[0], 30)
        self.assertEqual(sorted(total.control_rtt_ms.reservoir), [1.0, 2.0, 3.0])
        self.assertEqual(distribution(total.control_rtt_ms)["max"], 3.0)


class GazePatterns(unittest.TestCase):
    def test_every_pattern_stays_on_screen(self):
        for name in ("wandering", "circle", "fixed"):
            pattern = gaze_patterns.by_name(name)
            for i in range(5000):
                x, y = pattern(i * 0.005)
                self.assertTrue(0.0 <= x <= 1.0 and 0.0 <= y <= 1.0, (name, i, x, y))

    def test_wandering_moves_and_repeats_for_its_seed(self):
        a, b = gaze_patterns.Wandering(seed=3), gaze_patterns.Wandering(seed=3)
        points_a = [a(i * 0.01) for i in range(1000)]
        self.assertEqual(points_a, [b(i * 0.01) for i in range(1000)])
        xs = [p[0] for p in points_a]
        self.assertGreater(max(xs) - min(xs), 0.2)  # it wanders over the screen in 10 s


if __name__ == "__main__":
    unittest.main()
