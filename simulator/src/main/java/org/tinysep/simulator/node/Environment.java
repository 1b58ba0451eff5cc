package org.tinysep.simulator.node;

/** What the sensors of the flat perceive. Times are virtual epoch seconds. */
public interface Environment {

    /** @return true if a person moved in {@code room} at some second in ({@code after}, {@code upTo}] */
    boolean personMotion(String room, long after, long upTo);

    /** @return true if the pet {@code agent} moved at some second in ({@code after}, {@code upTo}] */
    boolean petMotion(String agent, long after, long upTo);

    /** @return true if the outer door in {@code room} stands open at {@code second} */
    boolean doorOpen(String room, long second);

    /** @return what the person {@code agent} is doing, for the node they wear; AWAY when not known */
    default Wearer wearer(String agent) {
        return Wearer.AWAY;
    }
}
