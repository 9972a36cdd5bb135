"""Configurations from dicts and TOML files pass the CLI's checks; mistakes raise ConfigError."""

import pytest

import orogen


def test_unknown_key_names_the_key():
    with pytest.raises(orogen.ConfigError, match=r"wedge\.s_ned"):
        orogen.load_config({"wedge": {"s_ned": 2}})


def test_bad_type_and_value_name_what_is_allowed():
    with pytest.raises(orogen.ConfigError, match=r"wedge\.s_end.*expected"):
        orogen.load_config({"wedge.s_end": "two"})
    with pytest.raises(orogen.ConfigError, match=r"run\.experiment.*wegde"):
        orogen.load_config({"run": {"experiment": "wegde"}})
    assert issubclass(orogen.ConfigError, ValueError)


def test_unsupported_python_value():
    with pytest.raises(orogen.ConfigError, match="expected a bool, int, float or string"):
        orogen.load_config({"wedge": {"s_end": [1, 2]}})


def test_dict_file_and_set_agree(tmp_path):
    nested = orogen.resolved_toml({"wedge": {"s_end": 2.5, "mu_bp": 0.3}, "run": {"seed": 7}})
    dotted = orogen.resolved_toml({"wedge.s_end": 2.5, "wedge.mu_bp": 0.3, "run.seed": 7})
    assert nested == dotted
    file = tmp_path / "c.toml"
    file.write_text(nested)
    assert orogen.resolved_toml(file) == nested
    assert "s_end = 2.5" in orogen.resolved_toml(file, set={"run.seed": 8}) and "seed = 8" in orogen.resolved_toml(
        file, set={"run.seed": 8})


def test_bad_file_key_names_the_file(tmp_path):
    file = tmp_path / "bad.toml"
    file.write_text("[wedge]\nbogus = 1\n")
    with pytest.raises(orogen.ConfigError, match=r"bad\.toml.*wedge\.bogus"):
        orogen.load_config(file)


def test_run_refuses_before_writing(tmp_path):
    with pytest.raises(orogen.ConfigError):
        orogen.run({"wedge": {"nope": 1}}, out=tmp_path / "r")
    assert not (tmp_path / "r").exists()
