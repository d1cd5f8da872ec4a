"""Case: from a file, a TOML string or a dict; get and set by the paths of --set; errors with file, line, key."""

import pytest

import vibroimpact as vi


def test_get_and_set_by_path(small_case):
    case = vi.Case.from_file(str(small_case))
    assert case.file == str(small_case)
    assert case.get("beam.elements") == 10 and isinstance(case.get("beam.elements"), int)
    assert case.get("supports[0].stiffness") == pytest.approx(1000.0)
    case.set("supports[0].stiffness", 2500.0)
    assert case.get("supports[0].stiffness") == 2500.0
    case.update({"supports[0].position": 0.75, "beam.elements": 12})
    assert case.get("supports[0].position") == 0.75 and case.get("beam.elements") == 12
    assert "supports[i].position" in vi.Case.paths()


def test_to_toml_reads_back_as_the_same_case(small_case):
    case = vi.Case.from_file(str(small_case))
    case.set("supports[0].stiffness", 2500.0)
    text = case.to_toml()
    assert "stiffness = 2500.0  # N/m" in text
    back = vi.Case.from_string(text)
    assert back.to_toml() == text and back.get("supports[0].stiffness") == 2500.0


def test_a_refused_value_leaves_the_case_unchanged_and_names_the_key(small_case):
    case = vi.Case.from_file(str(small_case))
    with pytest.raises(vi.InputError) as e:
        case.set("supports[0].position", 1.5)
    assert e.value.key == "supports[0].position"
    assert e.value.file == str(small_case)
    assert e.value.line == small_case.read_text().splitlines().index("position = 1.0         # x0/l: the free end") + 1
    assert case.get("supports[0].position") == 1.0
    with pytest.raises(vi.InputError) as e:
        case.set("supports[3].position", 0.5)
    assert "supports[3]" in str(e.value)


def test_a_bad_case_file_names_file_line_and_key(tmp_path, small_case):
    text = small_case.read_text().replace('width = "30 um"', 'width = "30 um"\nwidht = "3 um"')
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    with pytest.raises(vi.InputError) as e:
        vi.Case.from_file(str(bad))
    assert e.value.file == str(bad)
    assert e.value.line == text.splitlines().index('widht = "3 um"') + 1
    assert e.value.key == "beam.widht"
    assert isinstance(e.value, ValueError)
    with pytest.raises(vi.InputError) as e:
        vi.Case.from_file(str(tmp_path / "missing.toml"))
    assert e.value.file == str(tmp_path / "missing.toml")
    assert e.value.line is None


def test_toml_syntax_in_a_string_names_the_line():
    with pytest.raises(vi.InputError) as e:
        vi.Case.from_string('name = "x"\n[beam\nlength = 1\n', source="text.toml")
    assert e.value.file == "text.toml"
    assert e.value.line == 2


def test_from_string_and_from_dict_read_the_same_case(small_case):
    import tomllib

    text = small_case.read_text()
    by_file = vi.Case.from_file(str(small_case))
    by_text = vi.load(text)
    by_dict = vi.load(tomllib.loads(text))
    paths = ["beam.length", "beam.elements", "material.youngs_modulus", "supports[0].stiffness",
             "supports[0].position", "damping.ratios[1]", "solver.horizon"]
    for p in paths:
        assert by_text.get(p) == by_file.get(p), p
        assert by_dict.get(p) == by_file.get(p), p
    assert by_dict.name == by_file.name


def test_a_dict_with_a_bad_value_names_the_key(small_case):
    import tomllib

    data = tomllib.loads(small_case.read_text())
    data["supports"][0]["stiffness"] = "-5 N/m"
    with pytest.raises(vi.InputError) as e:
        vi.Case.from_dict(data)
    assert e.value.key == "supports[0].stiffness"
    assert e.value.file == "<dict>"
    data["supports"][0]["stiffness"] = object()
    with pytest.raises(vi.InputError) as e:
        vi.Case.from_dict(data)
    assert "supports[0].stiffness" in str(e.value)
