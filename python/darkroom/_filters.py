"""Passes written in Python. A subclass of Filter declares its ports and
computes on numpy arrays; register() makes it a node type of this process,
usable in any pipeline (built in code or loaded from a file)::

    class Invert(dr.Filter):
        type = "Invert"
        doc = "1 - colour"
        inputs = [dr.ImageIn("image", channels=["R", "G", "B"]), dr.FloatIn("amount", 1.0, 0.0, 1.0)]
        outputs = [dr.ImageOut("image")]

        def execute(self, image, amount):
            return image.with_channels({c: image[c] + amount * (1 - 2 * image[c]) for c in "RGB"})

    dr.register(Invert)

execute() is called with every input by its port name (an Image, a list
of Images for a `multiple` input, None for an unconnected optional one, or
the value) and returns an Image (when there is one output) or a dict of
output name: value. It runs under the interpreter lock, one Python pass at a
time, while native passes go on in parallel; an exception it raises becomes
the node's error ("node 'x' (Invert): Python ValueError: ...")."""
from . import _darkroom


def _port(kind, name, doc, **extra):
    spec = {"name": name, "type": kind, "doc": doc}
    spec.update({k: v for k, v in extra.items() if v is not None})
    return spec


def ImageIn(name, doc="", channels=(), optional=False, multiple=False):
    return _port("image", name, doc, channels=list(channels), optional=optional, multiple=multiple)


def ImageOut(name, doc="", channels=()):
    return _port("image", name, doc, channels=list(channels))


def FloatIn(name, default, minimum=None, maximum=None, doc=""):
    return _port("float", name, doc, default=float(default), minimum=minimum, maximum=maximum)


def IntIn(name, default, minimum=None, maximum=None, doc=""):
    return _port("int", name, doc, default=int(default), minimum=minimum, maximum=maximum)


def BoolIn(name, default, doc=""):
    return _port("bool", name, doc, default=bool(default))


def StringIn(name, default="", doc=""):
    return _port("string", name, doc, default=str(default))


def EnumIn(name, choices, default, doc=""):
    return _port("enum", name, doc, choices=list(choices), default=default)


def ColorIn(name, default, doc=""):
    return _port("color", name, doc, default=list(default))


def ValueOut(name, type, doc=""):
    """A value output: type one of float, int, bool, string, color, vec3, row."""
    return _port(type, name, doc)


class Filter:
    """Base of passes written in Python; see the module's text."""

    type = None
    category = "Python"
    doc = ""
    inputs = []
    outputs = []

    def execute(self, **inputs):
        raise NotImplementedError(f"{type(self).__name__}.execute")


def register(cls):
    """Registers a Filter subclass under its `type` (default: the class name);
    returns the class, so it also works as a decorator."""
    if not (isinstance(cls, type) and issubclass(cls, Filter)):
        raise TypeError(f"register: expected a subclass of darkroom.Filter, got {cls!r}")
    if not cls.outputs:
        raise ValueError(f"{cls.__name__}: declare at least one output (outputs = [dr.ImageOut('image')])")
    _darkroom._register_filter(cls.type or cls.__name__, cls.category, cls.doc or (cls.__doc__ or "").strip(),
                               list(cls.inputs), list(cls.outputs), cls, f"python ({cls.__module__}.{cls.__qualname__})")
    return cls
