"""Issue 29 item 2: a layer answers questions about its base through members, so no caller compares layer.base."""
from __future__ import annotations

import pytest

from thinlayer import BondedLayer, FrictionlessLayer, GenericLayer, HalfSpace
from thinlayer.errors import InputError
from thinlayer.layers.kernels import IncompressibleLayer, LayerKernel

#: layer -> (base_label, base_phrase, base_note, two-term, incompressible, edge shift, kernel depends on nu)
TABLE = {
    "bonded": (BondedLayer(0.3), ("bonded", "bonded to", "", True, True, True, True)),
    "bonded symbolic": (BondedLayer(), ("bonded", "bonded to", "", True, True, True, True)),
    "incompressible": (IncompressibleLayer(), ("bonded", "bonded to", "", True, True, False, True)),
    "frictionless": (FrictionlessLayer(0.3), ("frictionless", "lying without friction on", "frictionless base", False,
                                              False, True, False)),
    "half-space": (HalfSpace(), (None, None, "", False, False, False, False)),
    "generic": (GenericLayer(), (None, None, "", False, False, False, True)),
}


@pytest.mark.parametrize("key", sorted(TABLE))
def test_the_layer_answers_for_its_base(key):
    layer, want = TABLE[key]
    got = (layer.base_label, layer.base_phrase, layer.base_note, layer.has_two_term_model,
           layer.has_incompressible_model, layer.has_edge_shift, layer.kernel_depends_on_nu)
    assert got == want
    assert layer.on_rigid_base is (want[0] is not None)
    assert isinstance(layer.kernel_key, LayerKernel)


def test_with_nu_keeps_the_base():
    assert BondedLayer(0.3).with_nu(0.4) == BondedLayer(0.4)
    assert BondedLayer(0.3, dps=40).with_nu("1/3").dps == 40
    assert BondedLayer(0.3).with_nu("1/2") == IncompressibleLayer()  # (2.4): A = 0 at nu = 1/2
    assert IncompressibleLayer().with_nu(0.5) == IncompressibleLayer()
    assert IncompressibleLayer().with_nu(0.3) == BondedLayer(0.3)
    assert FrictionlessLayer().with_nu(0.3) == FrictionlessLayer(0.3)
    assert HalfSpace().with_nu(0.3) == HalfSpace()
    with pytest.raises(InputError, match="no base"):
        GenericLayer().with_nu(0.3)


def test_incompressible_at_and_kernel_key():
    assert BondedLayer(0.3).incompressible_at(0.5) and BondedLayer(0.3).incompressible_at("1/2")
    assert not BondedLayer(0.3).incompressible_at(0.49)
    assert IncompressibleLayer().incompressible_at(0.5)
    assert not FrictionlessLayer(0.3).incompressible_at(0.5)  # the frictionless kernel does not degenerate
    assert FrictionlessLayer(0.3).kernel_key == FrictionlessLayer()
    assert FrictionlessLayer(0.3).kernel_key.L() == FrictionlessLayer(0.3).L()  # the same kernel
    assert BondedLayer(0.3).kernel_key is not None and BondedLayer(0.3).kernel_key == BondedLayer(0.3)
