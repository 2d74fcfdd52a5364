"""The front door (thinlayer/__init__.py): a short grouped __all__, and the moved names warn for one release."""
import importlib

import pytest

import thinlayer


def test_all_is_short_and_importable():
    assert len(thinlayer.__all__) <= 36
    assert len(set(thinlayer.__all__)) == len(thinlayer.__all__)
    for name in thinlayer.__all__:
        assert getattr(thinlayer, name) is not None


@pytest.mark.parametrize("name", sorted(thinlayer._MOVED))
def test_a_moved_name_warns_and_is_the_same_object(name):
    module = importlib.import_module(thinlayer._MOVED[name])
    with pytest.warns(DeprecationWarning, match=f"import it from {thinlayer._MOVED[name]}"):
        obj = getattr(thinlayer, name)
    assert obj is getattr(module, name)
    assert name not in thinlayer.__all__


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'nothing_here'"):
        thinlayer.nothing_here  # noqa: B018
