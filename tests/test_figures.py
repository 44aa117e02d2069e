"""The plot rules' drawings that the book's pages used to draw themselves."""

from __future__ import annotations

import pytest


@pytest.mark.heavy
def test_figure2s_diagram_names_the_hidden_units_and_draws_the_same_png(tmp_path):
    """Figure 2's diagram (rule ``figure2_architecture``): a PNG, the same for the same config;
    the hidden layer's size is the config's."""
    from PIL import Image

    from icub_affordance.figures import figure2_architecture

    paths = [tmp_path / "a.png", tmp_path / "b.png", tmp_path / "c.png"]
    for path, hidden in zip(paths, (10, 10, 40), strict=True):
        figure2_architecture(hidden, path)
    assert paths[0].read_bytes() == paths[1].read_bytes() != paths[2].read_bytes()
    assert Image.open(paths[0]).size[0] > 600
