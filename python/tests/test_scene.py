"""load_scene: the scene loader with overrides, its keys by their path in the file (SI), and
bad input as InputError carrying the command's located message."""

import pytest

import frictionlab as fl
from conftest import SCENES, cli


def test_keys_by_path_in_si():
    scene = fl.load_scene(SCENES / "minimal.yaml")
    assert scene.name == "minimal" and scene.file == str(SCENES / "minimal.yaml")
    assert scene["rollers.spacing"] == pytest.approx(0.089, rel=1e-15)  # 89 mm
    assert scene["rollers.diameter"] == pytest.approx(0.020, rel=1e-15)
    assert scene["rollers.radius"] == pytest.approx(0.010, rel=1e-15)
    assert scene["world.time_step"] == pytest.approx(1e-3, rel=1e-15)
    assert scene["sensor.sample_rate"] == 1000.0
    assert scene["magnets.1.x"] == pytest.approx(0.095, rel=1e-15)
    assert scene["sensor.position"] == pytest.approx([0.115, 0.0, 0.015], rel=1e-15)
    # friction.mu_k: paper is Table I's value for the plate's material (LEGO blocks, 0.29).
    assert scene["friction.mu_k"] == 0.29
    assert scene["friction.paper_material"] == "lego"
    assert scene["friction.paper_period"].value == 0.79
    # Keys the file leaves out have their defaults; absent optional ones are None.
    assert scene["friction.mu_s"] is None and scene["drive"] is None
    assert scene["plate.mass"] is None and scene["plate.density"] == 1050.0
    assert scene["rollers.sense"] == "inward" and scene["friction.law"] == "coulomb"
    # The same values as attributes.
    assert scene.rollers.spacing == scene["rollers.spacing"]
    assert scene.magnets[1].x == scene["magnets.1.x"]


def test_the_paper_rigs_parts():
    scene = fl.load_scene(SCENES / "paper-rig.yaml")
    assert [(s.driver, s.driven) for s in scene["drive.gearbox.stages"]] == [(16, 8)] * 3
    assert scene["drive.coupling.idler_gear"] == 40 and scene["drive.ratio"] == 8.0
    assert scene["plate.blocks.0.part"] == "brick-2x4"
    assert len(scene["frame.parts"]) > 0


def test_unknown_key_says_what_it_might_be():
    scene = fl.load_scene(SCENES / "minimal.yaml")
    with pytest.raises(KeyError, match=r"has no key .*spacng.*did you mean .*spacing"):
        scene["rollers.spacng"]
    with pytest.raises(KeyError, match="magnets"):
        scene["magnets.2.x"]
    assert scene.get("rollers.spacng", "none") == "none"


def test_overrides_as_a_mapping_or_as_command_line_texts():
    a = fl.load_scene(SCENES / "minimal.yaml", set={"friction.mu_k": 0.3, "rollers.spacing": "100mm",
                                                    "drive": None})
    b = fl.load_scene(SCENES / "minimal.yaml", set=["friction.mu_k=0.3", "rollers.spacing=100mm"])
    for s in (a, b):
        assert s["friction.mu_k"] == 0.3 and s["rollers.spacing"] == pytest.approx(0.1, rel=1e-15)
        assert s["friction.paper_material"] is None
    assert a.overrides == {"friction.mu_k": "0.3", "rollers.spacing": "100mm", "drive": "null"}
    # Python values are written as the file would hold them: lists, maps, booleans.
    c = fl.load_scene(SCENES / "minimal.yaml",
                      set={"magnets": [{"x": "95mm"}], "output.hall": False})
    assert len(c["magnets"]) == 1 and c["output.hall"] is False


def test_with_set_is_a_new_scene():
    scene = fl.load_scene(SCENES / "minimal.yaml", set={"friction.mu_k": 0.3})
    wider = scene.with_set({"rollers.spacing": "120mm"})
    assert wider["rollers.spacing"] == pytest.approx(0.12, rel=1e-15)
    assert wider["friction.mu_k"] == 0.3  # its own overrides stay
    assert scene["rollers.spacing"] == pytest.approx(0.089, rel=1e-15)  # unchanged


def test_parse_scene_from_text():
    text = (SCENES / "minimal.yaml").read_text()
    scene = fl.parse_scene(text, "mine", set={"world.duration": "2s"})
    assert scene.file is None and scene["world.duration"] == 2.0
    a = fl.run(scene, record=False).json()
    b = fl.run(fl.load_scene(SCENES / "minimal.yaml"), duration="2s", record=False).json()
    for key in ("period_trajectory_s", "mu_k_recovered", "amplitude_end_m"):
        assert a[key] == b[key]


def command_error(*args):
    return cli("run", *args, status=2).stderr.strip()


def test_a_typo_in_a_scene_file_is_located(tmp_path):
    typo = tmp_path / "typo.yaml"
    typo.write_text((SCENES / "minimal.yaml").read_text().replace("  spacing: 89 mm",
                                                                    "  spacng: 89 mm"))
    with pytest.raises(fl.InputError) as caught:
        fl.load_scene(typo)
    assert str(caught.value) == command_error(typo)
    assert str(caught.value).startswith(f"{typo}:13:3: error: rollers.spacng: unknown key")
    assert "did you mean 'spacing'?" in str(caught.value)
    assert (caught.value.file, caught.value.line, caught.value.column) == (str(typo), 13, 3)
    assert isinstance(caught.value, ValueError)


def test_bad_overrides_are_the_commands_errors():
    # The same message; the override spelled as each front end takes it.
    with pytest.raises(fl.InputError) as caught:
        fl.load_scene(SCENES / "minimal.yaml", set={"rollers.spacing": "89xx"})
    expected = command_error(SCENES / "minimal.yaml", "--set", "rollers.spacing=89xx")
    assert str(caught.value) == expected.replace(
        "--set rollers.spacing=89xx:", "set={'rollers.spacing': '89xx'}:")
    assert caught.value.field == "set" and caught.value.file is None
    # A set-up the loader refuses as a whole, located at the key responsible.
    with pytest.raises(fl.InputError) as caught:
        fl.load_scene(SCENES / "minimal.yaml", set={"friction.mu_k": 10, "plate.thickness": "60mm"})
    assert str(caught.value) == command_error(SCENES / "minimal.yaml", "--set", "friction.mu_k=10",
                                              "--set", "plate.thickness=60mm")
    assert "no oscillation exists" in str(caught.value)


def test_bad_arguments_name_themselves():
    with pytest.raises(fl.InputError) as caught:
        fl.run(SCENES / "minimal.yaml", duration="5kg")
    expected = command_error(SCENES / "minimal.yaml", "--duration", "5kg")
    assert str(caught.value) == expected.replace("--duration:", "duration:")
    assert caught.value.file is None and caught.value.line is None
    assert caught.value.field == "duration"
    with pytest.raises(fl.InputError, match="no such file|cannot"):
        fl.load_scene(SCENES / "no-such-scene.yaml")
