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


def test_every_class_that_names_thinlayer_as_its_module_is_importable_from_it():
    """A class whose ``__module__`` is ``"thinlayer"`` (the errors, for readable tracebacks) must be an attribute of
    ``thinlayer``: pickling, and pytest-xdist sending a warning between processes, look it up there.  The
    ValidityWarning was not, and a worker of the two-process suite died on it ("no attribute 'ValidityWarning'").
    """
    from thinlayer import errors

    named = [obj for obj in vars(errors).values() if isinstance(obj, type) and obj.__module__ == "thinlayer"]
    assert len(named) >= 7
    for cls in named:
        assert getattr(thinlayer, cls.__name__) is cls
