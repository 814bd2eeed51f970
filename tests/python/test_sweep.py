"""lrchain.sweep(config): the sweep file run in the Python process gives the results file `lrchain
sweep --config` gives (the same points, bit for bit), resumes it, and refuses bad input naming the key."""

import numpy as np
import pytest

import lrchain

pytest.importorskip("h5py")
pytest.importorskip("xarray")


def _sweep_file(folder, output, values="[0.2, 1.0, 5.0]"):
    (folder / "base.toml").write_text('experiment = "regime intervals"\n[regime]\nsamples = 512\n')
    path = folder / "s.toml"
    path.write_text(f'job = "regime intervals"\nbase = "base.toml"\noutput = "{output}"\n'
                    f'[[axis]]\nparameter = "model.rho"\nvalues = {values}\n'
                    '[[axis]]\nparameter = "model.alpha"\nvalues = [1.2, 1.5]\n')
    return path


def test_same_results_as_the_command_and_resumed(tmp_path, cli):
    config = _sweep_file(tmp_path, tmp_path / "python.h5")
    ds = lrchain.sweep(config, threads=2, progress=False)
    cli("sweep", "--config", str(config), "--output", str(tmp_path / "cli.h5"), "--threads", "1", "--quiet")
    expected = lrchain.open_sweep(tmp_path / "cli.h5")
    assert ds.optical_intervals.dims == ("model.rho", "model.alpha") and (ds.status.values == 1).all()
    for name in expected.data_vars:
        if name != "wall_seconds":
            np.testing.assert_array_equal(ds[name].values, expected[name].values, err_msg=name)
    assert ds.attrs["sweep_config"] == expected.attrs["sweep_config"]
    # A second call finds every point finished: it keeps them (their run times too) and runs none.
    again = lrchain.sweep(config, threads=1, progress=False)
    np.testing.assert_array_equal(again.wall_seconds.values, ds.wall_seconds.values)


def test_bad_input_names_the_key(tmp_path):
    (tmp_path / "no_base.toml").write_text('job = "regime intervals"\noutput = "x.h5"\n'
                                           '[[axis]]\nparameter = "model.rho"\nvalues = [1.0]\n')
    with pytest.raises(lrchain.InputError, match="base"):
        lrchain.sweep(tmp_path / "no_base.toml", progress=False)
    config = _sweep_file(tmp_path, tmp_path / "out.h5")
    with pytest.raises(lrchain.InvalidParameterError, match="output") as e:
        lrchain.sweep(config, output=tmp_path, progress=False)  # a directory
    assert e.value.parameter == "output"
    assert not (tmp_path / "out.h5").exists()
