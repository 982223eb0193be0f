"""VerificationSession.check_configurations: the certified verdict of single configurations
(proofs/configuration-check.md), against the steps of a verification of the same cell
(data/sixaxis: the arm swings links 4 and 5 through the post), with the findings named as the
reports name them, and bad input refused with the row or option named."""
import numpy
import pytest

import grpvss
from conftest import SOURCE_DIR

SIXAXIS = SOURCE_DIR / "data" / "sixaxis"
CELL = str(SIXAXIS / "cell.yaml")


@pytest.fixture(scope="module")
def cell():
    return grpvss.load_cell(CELL)


def step_verdict(collides, interferes):
    if collides:
        return grpvss.Verdict.COLLISION
    return grpvss.Verdict.WITHIN_TOLERANCE if interferes else grpvss.Verdict.CLEAR


def test_every_step_of_a_verification_gets_the_verdict_its_flags_show(cell):
    result = cell.verify(str(SIXAXIS / "path-collision.txt"))
    verdicts = cell.session().check_configurations(result.configurations)
    assert len(verdicts) == result.step_count == 8
    expected = [step_verdict(c, e) for c, e in zip(result.unexpanded_collides,
                                                   result.expanded_interferes)]
    assert [v.verdict for v in verdicts] == expected
    assert [v.verdict.name for v in verdicts] == [
        "CLEAR", "CLEAR", "WITHIN_TOLERANCE", "COLLISION", "COLLISION", "CLEAR", "CLEAR", "CLEAR"]
    assert [v.clear for v in verdicts] == [v.verdict == grpvss.Verdict.CLEAR for v in verdicts]
    assert verdicts[0].findings == []


def test_findings_name_the_link_and_the_obstacle(cell):
    result = cell.verify(str(SIXAXIS / "path-collision.txt"))
    session = cell.session()
    grazing = session.check_configuration(result.configurations[2])
    assert [str(f) for f in grazing.findings] == ["link_4 / post: within tolerance",
                                                  "link_5 / post: within tolerance"]
    hit = session.check_configuration(result.configurations[3])
    assert [(f.kind, f.link, f.other) for f in hit.findings] == [
        ("collision", "link_4", "post"), ("collision", "link_5", "post")]
    post = cell.environment.obstacle_names.index("post")
    assert [f.obstacle for f in hit.findings] == [post, post]
    assert repr(hit) == "<ConfigurationVerdict COLLISION; link_4 / post: collision; link_5 / post: collision>"


def test_bad_configurations_are_refused_with_the_row_or_option_named(cell):
    session = cell.session()
    with pytest.raises(grpvss.InputError) as wrong_width:
        session.check_configurations(numpy.zeros((2, 5)))
    assert (wrong_width.value.file, wrong_width.value.line) == ("configurations", 0)
    assert wrong_width.value.expected == "6 columns (one per joint)"
    rows = numpy.zeros((3, 6))
    rows[1, 2] = numpy.nan
    with pytest.raises(grpvss.InputError) as not_finite:
        session.check_configurations(rows)
    assert (not_finite.value.file, not_finite.value.line) == ("configurations", 2)
    assert "joint 3" in not_finite.value.found
    with pytest.raises(grpvss.InputError) as thesis:
        cell.session(mode="thesis").check_configurations(rows[:1])
    assert thesis.value.file == "mode"
    assert session.check_configurations([]) == []
