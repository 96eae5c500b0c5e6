"""The negative control of test_typed_api.py: calls that run (or fail) only at run time, each of which
`mypy --strict` must report. Every line marked `# error: CODE` must get exactly that error, and no other
line any; the file is never run.
"""

import shadelab
import shadelab.lighting
from shadelab import _shadelab


def mistakes(scene: shadelab.Scene, name: str) -> None:
    shadelab.render(scene, (64, 64), renderer="trac")  # error: arg-type
    shadelab.render(scene, (64, 64), renderer=name)  # error: arg-type
    shadelab.render(scene, (64, 64), sppp=4)  # error: call-arg
    shadelab.render(scene, (64, 64), "trace")  # error: misc
    shadelab.render(scene, 640)  # error: arg-type
    shadelab.render(42)  # error: arg-type
    scene.render((8, 8), depth="deep")  # error: arg-type
    shadelab.Renderer(backend="vulkan")  # error: arg-type
    shadelab.render(scene, (64, 64), max_memory=1.5)  # error: arg-type
    shadelab.render(scene, (64, 64), view_transform="aces")  # error: arg-type
    shadelab.render(scene, (64, 64), exposure="bright")  # error: arg-type
    width: str = shadelab.render(scene).width  # error: assignment
    shadelab.render(scene, coverage=True).coverage.max()  # error: union-attr
    scene.base_dir = "elsewhere"  # error: misc
    shadelab.compare("a.png", "b.png", gain="high")  # error: arg-type
    shadelab.compare("a.png", "b.png", gates={"threshold": "3"})  # error: dict-item
    shadelab.lighting.shade([0, 0, 1], [0, 0, 1], [0, 0, 1], model="toon")  # error: arg-type
    _shadelab._probe(scene, 1, 2, 3, 4)  # error: arg-type
    _shadelab.Image.open("a.png").save(3)  # error: arg-type
    print(width)
