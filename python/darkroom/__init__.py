"""Darkroom for Python: Cinema databases, pipelines and images.

The same libraries, plugins, pipeline files and evaluator as ``darkroom run``
and the editor (docs/python.md)::

    import darkroom as dr
    db = dr.Database("sim.cdb")
    p = dr.Pipeline()
    read = p.add("CinemaReader", database=db.path)
    colour = p.add("ColorMapping", channel="Elevation", colormap="viridis")
    p.connect(read.image, colour.image)
    picture = p.evaluate(colour.image)      # an Image; picture["R"] is a numpy view
"""
import os as _os

from . import _darkroom
from ._darkroom import Camera, Database, DatabaseWriter, Error, Image, InputError, node_types, plugins
from ._paths import PLUGINS_FROM_PACKAGE as _PLUGINS_FROM_PACKAGE
from ._capture import CameraGrid, CameraList, Scene, capture
from ._filters import (BoolIn, ColorIn, EnumIn, Filter, FloatIn, ImageIn, ImageOut, IntIn, StringIn, ValueOut,
                       register)

__version__ = _darkroom.__version__
__all__ = ["Camera", "CameraGrid", "CameraList", "Database", "DatabaseWriter", "Error", "Image", "InputError", "Node", "Pipeline",
           "Port", "Scene", "capture", "node_types", "plugins", "plugin_problems", "Filter", "register", "ImageIn",
           "ImageOut", "FloatIn", "IntIn", "BoolIn", "StringIn", "EnumIn", "ColorIn", "ValueOut"]


def _search_path():
    # This package's own plugins first (build tree or install tree), then
    # DARKROOM_PLUGIN_PATH, as the runner does with its own folder.
    here = _os.path.dirname(_os.path.abspath(__file__))
    path = [_os.path.normpath(_os.path.join(here, _PLUGINS_FROM_PACKAGE))]
    path += [p for p in _os.environ.get("DARKROOM_PLUGIN_PATH", "").split(":") if p]
    return path


#: Plugins that could not be loaded, one line each (file and reason).
plugin_problems = _darkroom.load_plugins(_search_path())


class Port:
    """One port of a node: ``node.image``; what connect and evaluate take."""

    __slots__ = ("node", "name")

    def __init__(self, node, name):
        self.node, self.name = node, name

    def __str__(self):
        return f"{self.node}.{self.name}"

    def __repr__(self):
        return f"<darkroom.Port {self}>"


class Node:
    """A node of a Pipeline. ``node.port`` is a Port for images and outputs and
    the current value for a value input; ``node.port = value`` sets it."""

    def __init__(self, pipeline, name):
        object.__setattr__(self, "_pipeline", pipeline)
        object.__setattr__(self, "name", name)

    @property
    def type(self):
        return self._pipeline.node_type(self.name)

    def ports(self):
        return self._pipeline.ports(self.name)

    def port(self, name):
        if not any(p["name"] == name for p in self.ports()):
            raise AttributeError(f"node '{self.name}' ({self.type}) has no port '{name}'")
        return Port(self.name, name)

    def __getattr__(self, attr):
        ports = {}
        for p in self.ports():
            ports.setdefault(p["name"], []).append(p)
        if attr not in ports:
            names = ", ".join(sorted(ports))
            raise AttributeError(f"node '{self.name}' ({self.type}) has no port '{attr}'; ports: {names}")
        if any(p["output"] or p["type"] == "image" for p in ports[attr]):
            return Port(self.name, attr)
        return self._pipeline.get(self.name, attr)

    def __setattr__(self, attr, value):
        if isinstance(value, Port):
            self._pipeline.connect(value, Port(self.name, attr))
        else:
            self._pipeline.set(self.name, attr, value)

    def __repr__(self):
        return f"<darkroom.Node {self.name} ({self.type})>"


def _port(p, what):
    if isinstance(p, Port):
        return p.node, p.name
    if isinstance(p, str) and "." in p:
        node, name = p.split(".", 1)
        return node, name
    raise TypeError(f"{what}: expected a Port (node.image) or 'node.port', got {type(p).__name__}")


class Pipeline(_darkroom._Pipeline):
    """A node graph and its evaluator. Kept alive, it keeps the evaluator's
    cache: after an edit only what depends on it runs again (``last_run``)."""

    @classmethod
    def load(cls, path):
        """A pipeline file, as ``darkroom run`` reads it; relative paths in it
        resolve against its folder."""
        p = cls()
        p._load(path)
        return p

    def add(self, type, name=None, **parameters):
        """Adds a node of `type` (``darkroom.node_types()``) and sets its
        parameters; returns the Node."""
        node = Node(self, self._add(type, name or ""))
        for port, value in parameters.items():
            setattr(node, port, value)
        return node

    def node(self, name):
        if name not in self.node_names:
            raise KeyError(f"no node named '{name}'; nodes: {', '.join(self.node_names) or 'none'}")
        return Node(self, name)

    def __getitem__(self, name):
        return self.node(name)

    def connect(self, output, input):
        """Connects an output port to an input port: ``p.connect(read.image, colour.image)``."""
        self._connect(*_port(output, "output"), *_port(input, "input"))

    def disconnect(self, output, input):
        self._disconnect(*_port(output, "output"), *_port(input, "input"))

    def evaluate(self, output):
        """The value of an output port (an Image for images), computing only
        what the cache lacks."""
        return self._evaluate(*_port(output, "output"))

    def __repr__(self):
        return f"<darkroom.Pipeline {len(self.node_names)} nodes: {', '.join(self.node_names)}>"
