"""Synthesis files: read exactly, every fault one SceneError naming the element."""

import flint
import pytest

from algkin.errors import SceneError
from algkin.synthesis.files import read_task, read_task_text

POSES = """kind = "motion"
[[poses]]
x = 0
y = 0
angle = { cos = "1", sin = "0" }
[[poses]]
x = "1"
y = 0.5
angle = { cos = "3/5", sin = "4/5" }
[[poses]]
x = 2
y = 1
angle = 30
"""


def test_poses_are_read_exactly_and_degrees_are_said_to_be_approximate():
    task = read_task_text(POSES, "p.toml")
    assert task.kind == "motion" and task.name == "p"
    assert task.poses[1].y == flint.fmpq(1, 2) and task.poses[1].angle.sin == flint.fmpq(4, 5)
    thirty = task.poses[2].angle
    assert thirty.approximate and task.approximate
    assert thirty.cos**2 + thirty.sin**2 == 1  # exactly on the circle, within 1e-58 of 30 degrees
    assert abs(float(thirty.sin) - 0.5) < 1e-15 and abs(thirty.sin - flint.fmpq(1, 2)) < flint.fmpq(1, 10**58)


def test_function_and_path_files():
    function = read_task_text('kind = "function"\nunknown_start = true\nground = "5/2"\n'
                              '[[pairs]]\ninput = 0\noutput = { tan_half = "1/2" }\n', "f.toml")
    assert function.unknown_start and function.ground == flint.fmpq(5, 2)
    assert function.pairs[0].output.cos == flint.fmpq(3, 5)
    path = read_task_text('kind = "path"\npivots = { crank = [0, 0], rocker = ["4", 0] }\n'
                          '[[points]]\nx = 1\ny = "2/3"\n', "q.toml")
    assert path.pivots == ((0, 0), (4, 0)) and path.points == ((1, flint.fmpq(2, 3)),)


@pytest.mark.parametrize("text, element, words", [
    ('kind = "motoin"', "kind", "did you mean"),
    ('kind = "motion"\nposes = []\nwobble = 1', "wobble", "not a key of a motion file"),
    ('kind = "motion"\n[[poses]]\nx = 0\ny = 0\nangle = { cos = "1/2", sin = "1/2" }', "poses[0].angle", "not 1"),
    ('kind = "motion"\n[[poses]]\nx = 0\ny = 0\nangle = { cos = 1 }', "poses[0].angle", "tan_half"),
    ('kind = "motion"\n[[poses]]\nx = 0\nangle = 0', "poses[0].y", "missing"),
    ('kind = "motion"\n[[poses]]\nx = "__import__(1)"\ny = 0\nangle = 0', "poses[0].x", "not an exact number"),
    ('kind = "motion"\n[[poses]]\nx = true\ny = 0\nangle = 0', "poses[0].x", "exact number"),
    ('kind = "motion"\n[[poses]]\nx = 0\ny = 0\nangle = 0\nz = 1', "poses[0].z", "unknown key"),
    ('kind = "function"\nground = -1\npairs = []', "ground", "positive"),
    ('kind = "function"\nunknown_start = "yes"\npairs = []', "unknown_start", "true or false"),
    ('kind = "path"\npivots = { crank = [0, 0] }\npoints = []', "pivots", "rocker"),
    ('kind = "path"\npivots = { crank = [0, 0, 1], rocker = [1, 0] }\npoints = []', "pivots.crank", "[x, y]"),
    ('kind = ', "", "TOML syntax error"),
    ('kind = "motion"\n[[poses]]\nx = 1/2', "", 'write the fraction as a string: "1/2"'),
    # letters only, but past the 80 characters a file name takes: the message said "expected letters"
    ('kind = "motion"\nname = "' + "a" * 81 + '"', "name", "at most 80"),
])
def test_faults_name_the_element(text, element, words):
    with pytest.raises(SceneError) as err:
        read_task_text(text, "bad.toml")
    assert err.value.element == element and words in str(err.value) and "\n" not in str(err.value)


def test_files_that_are_not_regular_or_too_large(tmp_path):
    with pytest.raises(SceneError, match="not a regular file"):
        read_task(tmp_path)
    big = tmp_path / "big.toml"
    big.write_text('kind = "motion"\n' + "# pad\n" * 60000)
    with pytest.raises(SceneError, match="larger than"):
        read_task(big)
    with pytest.raises(SceneError, match="cannot read"):
        read_task(tmp_path / "absent.toml")


def test_a_file_with_a_byte_order_mark_reads_as_without(tmp_path):
    # Windows' Notepad starts UTF-8 with EF BB BF; it was "TOML syntax error: Invalid statement"
    with_mark, without = tmp_path / "marked.toml", tmp_path / "plain.toml"
    with_mark.write_bytes(b"\xef\xbb\xbf" + POSES.encode())
    without.write_bytes(POSES.encode())
    assert read_task(str(with_mark)).poses == read_task(str(without)).poses
