"""Library shapes of real ARGoS projects (issue 46, item 2; shapes_project): a controller and
the loop functions in one library named twice by the .argos (loaded once: they share its
statics), one controller label registered by two libraries (the last loaded gives the class,
as ARGoS's factory keeps the last registration), and a library no robot uses, loaded all the
same (its static initialiser's mark is seen by the other controllers' Init)."""
import pytest

from argos_projects import HERE, build_project, need_essaim, run

pytestmark = need_essaim


@pytest.fixture(scope="module")
def shapes(tmp_path_factory):
    return build_project(HERE / "shapes_project", tmp_path_factory.mktemp("shapes"))


def test_library_shapes(shapes, tmp_path):
    done = run(shapes / "shapes.argos", "--out", str(tmp_path / "out"), cwd=shapes)
    assert done.returncode == 0, done.stderr
    # Both word_controller entries get the class of word_second, loaded after word_first.
    assert "fb0 is second; unused library loaded: yes" in done.stdout, done.stdout
    assert "fb1 is second; unused library loaded: yes" in done.stdout, done.stdout
    assert " is first" not in done.stdout
    # libboth loaded once for its two entries: the loop functions count fb2's 10 steps.
    assert "both: the loop functions saw 10 steps" in done.stdout, done.stdout


def test_the_label_registered_twice_follows_the_load_order(shapes, tmp_path):
    text = (shapes / "shapes.argos").read_text()
    swapped = text.replace("build/libword_first", "FIRST").replace("build/libword_second", "build/libword_first")
    argos = shapes / "swapped.argos"
    argos.write_text(swapped.replace("FIRST", "build/libword_second"))
    done = run(argos, "--out", str(tmp_path / "out"), cwd=shapes)
    assert done.returncode == 0, done.stderr
    assert "fb0 is first" in done.stdout and "fb1 is first" in done.stdout, done.stdout


def test_an_unused_library_that_is_missing_is_still_an_error(shapes, tmp_path):
    """Declared libraries are loaded whether used or not, so a missing one stops the run."""
    argos = shapes / "missing.argos"
    argos.write_text((shapes / "shapes.argos").read_text().replace("build/libunused", "build/libnowhere"))
    done = run(argos, "--out", str(tmp_path / "out"), cwd=shapes)
    assert done.returncode == 2 and "libnowhere" in done.stderr, done.stderr
