"""Views and plugins from Python: geomesh.view, geomesh.view.option and geomesh.plugin act on
the session's views as a script's View, View[n].X and Plugin statements do."""

import pytest

import geomesh

view = geomesh.view
geo = geomesh.model.geo


# Each test starts from an empty model with default options, and leaves none behind.
pytestmark = pytest.mark.usefixtures("api_session")


def meshed_square():
    corners = [(0, 0), (1, 0), (1, 1), (0, 1)]
    points = [geo.addPoint(x, y, 0, 0.5) for x, y in corners]
    lines = [geo.addLine(points[k], points[(k + 1) % 4]) for k in range(4)]
    geo.addPlaneSurface([geo.addCurveLoop(lines)])
    geo.synchronize()
    geomesh.model.mesh.generate(2)


def test_views_are_added_listed_and_removed():
    a = view.add("a")
    b = view.add("b")
    assert view.getTags() == [a, b]
    assert view.getIndex(b) == 1
    view.remove(a)
    assert view.getTags() == [b] and view.getIndex(b) == 0
    assert view.add("c", tag=7) == 7
    assert view.add("d") == 8  # past the tag chosen
    with pytest.raises(geomesh.Error, match="no view has tag 42"):
        view.remove(42)


def test_list_data_is_written_as_pos_and_merged_back(tmp_path):
    tag = view.add("points")
    # Two scalar points: x, y, z then the value of each.
    view.addListData(tag, "SP", 2, [0, 0, 0, 1.5, 1, 2, 3, 2.5])
    assert view.option.getNumber(tag, "NbElements") == 2
    assert view.option.getNumber(tag, "Max") == 2.5
    path = tmp_path / "points.pos"
    view.write(tag, str(path))
    text = path.read_text()
    assert "SP(" in text and "points" in text
    geomesh.merge(path)
    tags = view.getTags()
    assert len(tags) == 2
    assert view.option.getString(tags[1], "Name") == "points"
    assert view.option.getNumber(tags[1], "Min") == 1.5


def test_list_data_of_the_wrong_size_raises():
    tag = view.add("bad")
    with pytest.raises(geomesh.Error, match="ST elements take 9 coordinates"):
        view.addListData(tag, "ST", 1, [0] * 10)
    with pytest.raises(geomesh.Error, match="not a list data type"):
        view.addListData(tag, "XX", 1, [0] * 4)


def test_texts_are_kept():
    tag = view.add("comments")
    view.addListDataString(tag, [10, -10], ["Created with geomesh"])
    view.addListDataString(tag, [0, 0.1, 0], ["Hole"], ["Align", "Center"])
    with pytest.raises(geomesh.Error):
        view.addListDataString(tag, [0], ["nowhere"])


def test_model_data_on_the_nodes_of_a_meshed_square(tmp_path):
    meshed_square()
    node_tags, coords, _ = geomesh.model.mesh.getNodes()
    xs = coords.reshape(-1, 3)[:, 0]
    tag = view.add("x")
    view.addModelData(tag, 0, "", "NodeData", list(node_tags), [[x] for x in xs])
    assert view.option.getNumber(tag, "Max") == pytest.approx(1)
    assert view.option.getNumber(tag, "Min") == pytest.approx(0)
    assert view.option.getNumber(tag, "NbTimeStep") == 1
    assert view.option.getNumber(tag, "NbElements") > 0
    view.addHomogeneousModelData(tag, 1, "", "NodeData", list(node_tags), list(2 * xs),
                                 time=1.0)
    assert view.option.getNumber(tag, "NbTimeStep") == 2
    assert view.option.getNumber(tag, "Max") == pytest.approx(2)
    path = tmp_path / "x.msh"
    view.write(tag, str(path))
    assert "$NodeData" in path.read_text()
    with pytest.raises(geomesh.Error, match="no node has tag"):
        view.addModelData(tag, 2, "", "NodeData", [len(node_tags) + 1], [[0.0]])


def test_view_options_are_set_and_read_back():
    tag = view.add("v")
    view.option.setNumber(tag, "IntervalsType", 2)
    view.option.setString(tag, "Name", "renamed")
    view.option.setString(tag, "Format", "%.3g")
    view.option.setColor(tag, "Color.Points", 255, 0, 0)
    assert view.option.getNumber(tag, "IntervalsType") == 2
    assert view.option.getNumber(tag, "NotSet") == 0
    assert view.option.getString(tag, "Name") == "renamed"
    assert view.option.getString(tag, "Format") == "%.3g"
    assert view.option.getColor(tag, "Color.Points") == (255, 0, 0, 255)


def test_math_eval_makes_a_new_view():
    tag = view.add("points")
    view.addListData(tag, "SP", 2, [0, 0, 0, 1, 1, 1, 1, 3])
    geomesh.plugin.setString("MathEval", "Expression0", "2 * v0")
    geomesh.plugin.setNumber("MathEval", "View", 0)
    made = geomesh.plugin.run("MathEval")
    assert made != tag and view.getTags() == [tag, made]
    assert view.option.getNumber(made, "Max") == 6


def test_a_display_plugin_makes_no_view():
    geomesh.plugin.setString("Annotate", "Text", "A title")
    assert geomesh.plugin.run("Annotate") == -1


def test_a_plugin_error_and_an_unknown_plugin_raise():
    geomesh.plugin.setNumber("MathEval", "View", 3)
    with pytest.raises(geomesh.Error):
        geomesh.plugin.run("MathEval")
    with pytest.raises(geomesh.Error, match="unknown plugin 'NoSuchPlugin'"):
        geomesh.plugin.run("NoSuchPlugin")


def test_simple_partition_partitions_the_mesh():
    meshed_square()
    geomesh.plugin.setNumber("SimplePartition", "NumSlicesX", 2)
    assert geomesh.plugin.run("SimplePartition") == -1
    geomesh.plugin.setNumber("SimplePartition", "NumSlicesX", 0)
    with pytest.raises(geomesh.Error, match="at least 1"):
        geomesh.plugin.run("SimplePartition")
