"""Image files and comparisons the module's tests share: EXR through OpenImageIO's own Python
binding (independent of rmfx), and bit-for-bit equality of float32 arrays (NaN included)."""
import numpy as np
import OpenImageIO as oiio


def read_exr(path):
    image = oiio.ImageInput.open(str(path))
    assert image, oiio.geterror()
    pixels = image.read_image("float")
    image.close()
    return np.asarray(pixels, dtype=np.float32)


def write_exr(path, array):
    out = oiio.ImageOutput.create(str(path))
    spec = oiio.ImageSpec(array.shape[1], array.shape[0], array.shape[2], "float")
    assert out.open(str(path), spec), oiio.geterror()
    assert out.write_image(array)
    out.close()


def assert_bit_equal(module, cli):
    assert module.dtype == np.float32 and module.shape == cli.shape, (module.shape, cli.shape)
    differ = module.view(np.uint32) != cli.view(np.uint32)
    assert not differ.any(), f"{int(differ.sum())} channels differ, the first at {np.argwhere(differ)[0].tolist()}"
