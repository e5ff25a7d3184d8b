"""What plots/railbench/precision_errors.py still computes for the figures of `workbench
precision`: the Pareto front and the quantities' labels and units (the errors and the
verification are the engine's: tests/precision/test_precision_answer.cpp)."""

import pytest

from railbench.precision_errors import QuantityError, parse_quantities, pareto


def test_pareto():
    pts = [(1.0, 1.0), (0.5, 2.0), (0.8, 3.0), (0.01, 10.0), (0.02, 20.0)]
    assert pareto(pts) == [0, 1, 3]


def test_bad_quantity():
    with pytest.raises(QuantityError):
        parse_quantities("y,lateral")
    assert [q.unit for q in parse_quantities("y,yaw,Q,Fy,Y,YQ,car.roll")] == \
        ["mm", "mrad", "kN", "kN", "kN", "-", "mrad"]
