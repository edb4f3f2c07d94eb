package dev.strahl.io.text;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashMap;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class LongIntMapTest {

    @Test
    void agreesWithAHashMapThroughManyRehashes() {
        var random = new SplittableRandom(3);
        var map = new LongIntMap();
        Map<Long, Integer> reference = new HashMap<>();
        for (int i = 0; i < 200_000; i++) {
            // Keys as ObjReader makes them (position << 32 | normal + 1), often repeated, sometimes huge
            long key = random.nextInt(4) == 0 ? random.nextLong(Long.MAX_VALUE)
                    : ((long) random.nextInt(50_000) << 32) | random.nextInt(3);
            Integer expected = reference.putIfAbsent(key, i);
            assertThat(map.putIfAbsent(key, i)).as("key %d", key).isEqualTo(expected == null ? -1 : expected);
        }
        assertThat(reference.size()).as("the test reached well past the first table size").isGreaterThan(100_000);
    }

    @Test
    void keyZeroIsAnOrdinaryKey() {
        var map = new LongIntMap();
        assertThat(map.putIfAbsent(0, 7)).isEqualTo(-1);
        assertThat(map.putIfAbsent(0, 8)).isEqualTo(7);
    }
}
