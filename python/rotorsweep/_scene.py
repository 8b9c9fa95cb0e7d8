"""Scene arguments of rotorsweep.run: TOML text, a path to a scene file, or a dict written out as
TOML (the same parser validates all three; docs/architecture.md "Python module")."""

import json
import math
import os
from pathlib import Path


def _toml_value(value, key):
    if hasattr(value, "tolist"):  # numpy scalars and arrays
        value = value.tolist()
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, dict):
        items = ", ".join(f"{_toml_key(k)} = {_toml_value(v, f'{key}.{k}')}" for k, v in value.items())
        return "{ " + items + " }" if items else "{}"
    if isinstance(value, (list, tuple, range)):
        return "[" + ", ".join(_toml_value(v, key) for v in value) + "]"
    raise ValueError(f"scene key '{key}': a {type(value).__name__} cannot be written as TOML")


def _toml_key(key):
    if not isinstance(key, str):
        raise ValueError(f"scene key {key!r}: keys are strings")
    bare = key and all(c.isalnum() or c in "_-" for c in key)
    return key if bare else json.dumps(key)


def dict_to_toml(scene):
    """The TOML text of a scene given as a dict of tables ({"sweep": {"A": [1, 2]}, ...})."""
    lines = []
    for key, value in scene.items():
        if not isinstance(value, dict):
            lines.append(f"{_toml_key(key)} = {_toml_value(value, key)}")
    for key, value in scene.items():
        if isinstance(value, dict):
            lines.append(f"\n[{_toml_key(key)}]")
            for inner, item in value.items():
                lines.append(f"{_toml_key(inner)} = {_toml_value(item, f'{key}.{inner}')}")
    return "\n".join(lines).lstrip("\n") + "\n"


def resolve(scene):
    """(text or path, is_path) for the engine; a path must exist, a str is a path when it names an
    existing file or ends in .toml, TOML text otherwise."""
    if isinstance(scene, dict):
        return dict_to_toml(scene), False
    if isinstance(scene, os.PathLike):
        scene = os.fspath(scene)
        is_path = True
    elif isinstance(scene, str):
        is_path = "\n" not in scene and (scene.endswith(".toml") or Path(scene).is_file())
    else:
        raise TypeError(f"scene: a dict, TOML text or a path, not {type(scene).__name__}")
    if is_path and not Path(scene).is_file():
        raise FileNotFoundError(f"scene file '{scene}' does not exist")
    return scene, is_path
