package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.image.Image;
import dev.strahl.image.ToneMapping;
import dev.strahl.color.DisplayEncoding;
import java.awt.image.BufferedImage;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Tone mapping for display: exposure, re-conversion without re-rendering, whole-image swaps. */
class FramePresenterTest {
    final FramePresenter presenter = new FramePresenter();
    final Semaphore shown = new Semaphore(0);

    FramePresenterTest() {
        presenter.onShown(shown::release);
    }

    @AfterEach
    void close() {
        presenter.close();
    }

    /** A 2×1 image: a grey of radiance {@code v} and black. */
    static RenderController.Frame frame(float v, long generation) {
        return new RenderController.Frame(new Image(2, 1, new float[] {v, v, v, 0, 0, 0}), 1, false, generation, Optional::empty);
    }

    FramePresenter.Shown awaitShown() throws InterruptedException {
        assertThat(shown.tryAcquire(5, TimeUnit.SECONDS)).as("a frame was converted").isTrue();
        return presenter.shown();
    }

    static int red(BufferedImage img, int x) {
        return (img.getRGB(x, 0) >> 16) & 0xFF;
    }

    @Test
    void convertsToSrgbLikeThePngWriter() throws Exception {
        presenter.accept(frame(0.2f, 1));
        FramePresenter.Shown s = awaitShown();
        assertThat(s.image().getWidth()).isEqualTo(2);
        assertThat(red(s.image(), 0)).isEqualTo(DisplayEncoding.toSrgb8(0.2f));
        assertThat(red(s.image(), 1)).isZero();
        assertThat(s.image().getType()).isEqualTo(BufferedImage.TYPE_INT_RGB);
    }

    /** The tone-mapping menu's curves: each re-converts the last frame as the PNG writer would, without a new frame. */
    @Test
    void aToneCurveReconvertsTheLastFrameAsThePngWriterWould() throws Exception {
        presenter.accept(frame(2.5f, 1));
        assertThat(red(awaitShown().image(), 0)).as("clamped").isEqualTo(255);
        for (ToneMapping curve : new ToneMapping[] {ToneMapping.ACES, ToneMapping.AGX}) {
            presenter.setToneMapping(curve);
            FramePresenter.Shown s = awaitShown();
            assertThat(s.curve()).isEqualTo(curve);
            BufferedImage expected = DisplayEncoding.toBufferedImage(new Image(2, 1, new float[] {2.5f, 2.5f, 2.5f, 0, 0, 0}), 0, curve);
            assertThat(s.image().getRGB(0, 0)).as("%s", curve).isEqualTo(expected.getRGB(0, 0));
            assertThat(red(s.image(), 0)).as("%s keeps 2.5 below white", curve).isLessThan(255);
        }
        assertThat(ToneMenu.menu(presenter).getItemCount()).isEqualTo(ToneMapping.values().length);
    }

    @Test
    void eachStopOfExposureDoublesTheDisplayedRadianceWithoutANewFrame() throws Exception {
        presenter.accept(frame(0.1f, 1));
        BufferedImage before = awaitShown().image();
        presenter.setExposure(1);
        FramePresenter.Shown after = awaitShown();
        assertThat(red(after.image(), 0)).isEqualTo(DisplayEncoding.toSrgb8(0.1f * 2.0));
        assertThat(after.exposure()).isEqualTo(1);
        assertThat(after.image()).as("a new image is swapped in, the old one is not changed").isNotSameAs(before);
        assertThat(red(before, 0)).isEqualTo(DisplayEncoding.toSrgb8(0.1f));
        presenter.setExposure(-2);
        assertThat(red(awaitShown().image(), 0)).isEqualTo(DisplayEncoding.toSrgb8(0.1f * 0.25));
    }

    @Test
    void exposureIsClampedAndMustBeFinite() {
        presenter.setExposure(100);
        assertThat(presenter.exposure()).isEqualTo(FramePresenter.MAX_EXPOSURE);
        assertThatThrownBy(() -> presenter.setExposure(Double.NaN)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void framesOfAReplacedJobAreDropped() throws Exception {
        presenter.accept(frame(0.5f, 3));
        awaitShown();
        presenter.accept(frame(0.9f, 2));
        assertThat(presenter.latest().generation()).isEqualTo(3);
        assertThat(shown.tryAcquire(200, TimeUnit.MILLISECONDS)).isFalse();
        assertThat(red(presenter.shown().image(), 0)).isEqualTo(DisplayEncoding.toSrgb8(0.5f));
    }

    /** View → Denoise: the denoised frame of the job on screen is shown (and would be saved) instead of its noisy frames. */
    @Test
    void withDenoiseOnTheDenoisedFrameOfTheCurrentJobIsShown() throws Exception {
        presenter.accept(frame(0.2f, 1));
        awaitShown();
        presenter.setDenoised(true);
        presenter.acceptDenoised(frame(0.4f, 1));
        FramePresenter.Shown s = awaitShown();
        assertThat(s.denoised()).isTrue();
        assertThat(red(s.image(), 0)).isEqualTo(DisplayEncoding.toSrgb8(0.4f));
        presenter.accept(frame(0.3f, 1));
        assertThat(presenter.pick().denoised()).as("a newer noisy frame of the same job waits for its denoise").isTrue();
        assertThat(presenter.pick().frame().image().get(0, 0, 0)).isEqualTo(0.4f);

        presenter.setDenoised(false);
        s = awaitShown();
        assertThat(s.denoised()).isFalse();
        assertThat(red(s.image(), 0)).isEqualTo(DisplayEncoding.toSrgb8(0.3f));
        presenter.setDenoised(true);
        assertThat(awaitShown().denoised()).isTrue();

        presenter.accept(frame(0.6f, 2));
        s = awaitShown();
        assertThat(s.denoised()).as("a new job: noisy until its first denoised frame").isFalse();
        assertThat(red(s.image(), 0)).isEqualTo(DisplayEncoding.toSrgb8(0.6f));
        presenter.acceptDenoised(frame(0.5f, 1));
        assertThat(presenter.pick().denoised()).as("a late result of the old job is dropped").isFalse();
    }

    /** The first conversion waits until every frame is in: which thread runs faster under load must not decide the test. */
    @Test
    void manyFramesAtOnceEndWithTheNewestShown() throws Exception {
        CountDownLatch allIn = new CountDownLatch(1);
        presenter.onShown(() -> {
            try {
                allIn.await(5, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        for (int i = 1; i <= 200; i++) {
            presenter.accept(frame(i / 200f, 1));
        }
        allIn.countDown();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while (System.nanoTime() < deadline && red(presenter.shown() == null ? new BufferedImage(2, 1, 1) : presenter.shown().image(), 0) != 255) {
            shown.tryAcquire(50, TimeUnit.MILLISECONDS);
        }
        assertThat(red(presenter.shown().image(), 0)).isEqualTo(255);
        assertThat(shown.availablePermits()).as("coalesced: far fewer conversions than frames").isLessThan(200);
    }
}
