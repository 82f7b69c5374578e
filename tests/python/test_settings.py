"""slamkit.settings: the pipeline's settings as a nested dict, with the checks of YAML files."""
import pytest

import slamkit


def test_defaults_and_overrides():
    defaults = slamkit.settings()
    assert defaults["orb"]["num_features"] == 1000
    assert defaults["orb"]["spread_over_image"] is True
    assert defaults["matcher"]["backend"] == "flann_lsh"
    assert defaults["tracking"]["ransac"]["threshold_base"] == 0.02
    changed = slamkit.settings({"orb": {"num_features": 500},
                                "tracking": {"ransac": {"threshold_base": 1e-6}}})
    assert changed["orb"]["num_features"] == 500
    assert changed["tracking"]["ransac"]["threshold_base"] == 1e-6
    assert changed["orb"]["pyramid_levels"] == defaults["orb"]["pyramid_levels"]
    assert slamkit.settings(changed) == changed


def test_a_dict_reads_as_the_same_yaml_file(tmp_path):
    path = tmp_path / "mine.yaml"
    path.write_text("orb:\n  num_features: 700\nmatcher:\n  mutual_check: false\n")
    assert slamkit.settings(path) == slamkit.settings(
        {"orb": {"num_features": 700}, "matcher": {"mutual_check": False}})


@pytest.mark.parametrize("settings, message", [
    ({"orb": {"num_featurs": 3}}, "settings:2: unknown setting 'orb.num_featurs'"),
    ({"orbs": {}}, "settings:1: unknown setting 'orbs'"),
    ({"orb": {"num_features": 0}}, "settings:2: orb.num_features: 0 is outside 1..100000"),
    ({"orb": {"num_features": 2.5}}, "settings:2: orb.num_features has the wrong type: '2.5'"),
    ({"orb": {"num_features": [1]}},
     "settings: 'orb.num_features' holds a list, not a number, a string, a bool or a dict"),
    ({"orb": {1: 2}}, "settings: key 1 in 'orb' is not a string"),
])
def test_bad_settings_raise_value_error_naming_the_key(settings, message):
    with pytest.raises(ValueError) as raised:
        slamkit.settings(settings)
    assert str(raised.value).startswith(message), str(raised.value)
