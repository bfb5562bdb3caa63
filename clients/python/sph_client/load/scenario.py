"""sph_load scenarios: phases of load, each with a duration and its traffic.

A scenario file is JSON:

    {"name": "ramp",
     "phases": [
       {"name": "warm", "duration_s": 10, "subscribers": 1},
       {"name": "full", "duration_s": 60, "subscribers": 8, "gaze_publishers": 2, "gaze_hz": 200,
        "gaze_pattern": "wandering", "pose_hz": 60, "control_hz": 2,
        "control_verbs": ["status", {"verb": "set_parameters", "values": {"gaze_radius": 0.06}}]}]}

Keys left out take the defaults of Phase below; unknown keys are errors (a typo would otherwise
silently run a different test).
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field, fields
from typing import Any, Union

from .. import gaze_patterns
from ..control import build_request

MAX_TOTAL_S = 24 * 3600.0  # a load test ends by itself; nobody means a week-long one
MAX_RATE_HZ = 10000.0
MAX_WORKERS = 256

ControlVerb = Union[str, dict]


class ScenarioError(ValueError):
    pass


@dataclass
class Phase:
    name: str = "phase"
    duration_s: float = 10.0
    subscribers: int = 1
    gaze_publishers: int = 0
    gaze_hz: float = 120.0
    gaze_pattern: str = "wandering"
    pose_hz: float = 0.0
    control_hz: float = 0.0
    control_verbs: list = field(default_factory=lambda: ["status"])

    def describe(self) -> str:
        parts = [f"{self.subscribers} subscribers"]
        if self.gaze_publishers:
            parts.append(f"{self.gaze_publishers} gaze x {self.gaze_hz:g} Hz ({self.gaze_pattern})")
        if self.pose_hz:
            parts.append(f"pose {self.pose_hz:g} Hz")
        if self.control_hz:
            parts.append(f"control {self.control_hz:g} Hz")
        return ", ".join(parts)


@dataclass
class Scenario:
    name: str
    phases: list

    @property
    def duration_s(self) -> float:
        return sum(p.duration_s for p in self.phases)

    def max_of(self, attribute: str) -> int:
        return max(getattr(p, attribute) for p in self.phases)

    def to_json(self) -> dict:
        return {"name": self.name, "phases": [asdict(p) for p in self.phases]}


def verb_arguments(verb: ControlVerb) -> tuple[str, dict]:
    """('set_parameters', {'values': {...}}) for one entry of control_verbs."""
    if isinstance(verb, str):
        return verb, {}
    if isinstance(verb, dict) and isinstance(verb.get("verb"), str):
        arguments = {k: v for k, v in verb.items() if k != "verb"}
        return verb["verb"], arguments
    raise ScenarioError(f"control verb {verb!r}: a name or an object with 'verb'")


def _check_phase(p: Phase, where: str) -> None:
    def number(name, lo, hi):
        value = getattr(p, name)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not lo <= value <= hi:
            raise ScenarioError(f"{where}.{name} = {value!r}: must be a number in {lo}..{hi}")

    def count(name):
        value = getattr(p, name)
        if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= MAX_WORKERS:
            raise ScenarioError(f"{where}.{name} = {value!r}: must be an integer in 0..{MAX_WORKERS}")

    if not isinstance(p.name, str):
        raise ScenarioError(f"{where}.name must be a string")
    number("duration_s", 0.1, MAX_TOTAL_S)
    count("subscribers")
    count("gaze_publishers")
    number("gaze_hz", 0.0, MAX_RATE_HZ)
    number("pose_hz", 0.0, MAX_RATE_HZ)
    number("control_hz", 0.0, MAX_RATE_HZ)
    if p.gaze_publishers and p.gaze_hz <= 0:
        raise ScenarioError(f"{where}: gaze_publishers > 0 needs gaze_hz > 0")
    try:
        gaze_patterns.by_name(p.gaze_pattern)
    except ValueError as error:
        raise ScenarioError(f"{where}.gaze_pattern: {error}") from None
    if not isinstance(p.control_verbs, list) or not p.control_verbs:
        raise ScenarioError(f"{where}.control_verbs must be a non-empty list")
    for verb in p.control_verbs:
        name, arguments = verb_arguments(verb)
        try:
            build_request(name, 0, **arguments)  # the same code that will send it
        except (ValueError, KeyError, TypeError) as error:
            raise ScenarioError(f"{where}.control_verbs: {verb!r}: {error}") from None


def scenario_from_dict(data: Any, default_name: str = "scenario") -> Scenario:
    if not isinstance(data, dict):
        raise ScenarioError("a scenario is a JSON object with 'phases'")
    unknown = set(data) - {"name", "description", "phases"}
    if unknown:
        raise ScenarioError(f"unknown scenario keys: {', '.join(sorted(unknown))}")
    raw_phases = data.get("phases")
    if not isinstance(raw_phases, list) or not raw_phases:
        raise ScenarioError("'phases' must be a non-empty list")
    allowed = {f.name for f in fields(Phase)}
    phases = []
    for i, raw in enumerate(raw_phases):
        where = f"phases[{i}]"
        if not isinstance(raw, dict):
            raise ScenarioError(f"{where} must be an object")
        unknown = set(raw) - allowed
        if unknown:
            raise ScenarioError(f"{where}: unknown keys: {', '.join(sorted(unknown))}")
        phase = Phase(**{"name": f"phase{i + 1}", **raw})
        _check_phase(phase, where)
        phases.append(phase)
    scenario = Scenario(str(data.get("name", default_name)), phases)
    if scenario.duration_s > MAX_TOTAL_S:
        raise ScenarioError(f"phases last {scenario.duration_s} s in all, more than {MAX_TOTAL_S} s")
    return scenario


def load_scenario(path: str) -> Scenario:
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, json.JSONDecodeError) as error:
        raise ScenarioError(f"{path}: {error}") from None
    return scenario_from_dict(data, default_name=path)


def single_phase(**values) -> Scenario:
    """The scenario of sph_load's command-line options alone: one phase."""
    phase = Phase(name="load", **values)
    _check_phase(phase, "options")
    return Scenario("command line", [phase])
